package xpbdcloth.scene;

import java.util.Locale;
import xpbdcloth.engine.Aerodynamics;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.DihedralBlock;
import xpbdcloth.engine.EnclosedGas;
import xpbdcloth.engine.HingePlasticity;
import xpbdcloth.fabric.Fabric;
import xpbdcloth.fabric.FabricConstraints;
import xpbdcloth.fabric.FabricSwap;
import xpbdcloth.fabric.MeasuredStiffening;
import xpbdcloth.fabric.PanelFabrics;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.MeshClothBuilder;
import xpbdcloth.engine.MeshCollider;
import xpbdcloth.engine.Plane;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.Sphere;
import xpbdcloth.engine.SpherePath;
import xpbdcloth.engine.Box;
import xpbdcloth.engine.Capsule;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.SelfCollision;
import xpbdcloth.engine.Sewing;
import xpbdcloth.engine.Wind;
import xpbdcloth.mesh.TriangleIntersections;

/**
 * A running scene: the cloth, simulation, spheres, scripted pins and wind that a {@link Preset}
 * describes. Building a scene validates everything first and touches nothing that already runs, so a
 * scene that fails to build leaves the caller's current scene as it was.
 */
public final class Scene {
    private final Preset preset;
    private final Cloth cloth;
    private final Simulation simulation;
    private final Wind wind;
    private final double scriptEnd;
    private boolean windOn;
    /** The fabric the cloth is now (null if it is springs): the preset's, until {@link #useFabric}. */
    private Fabric fabric;
    /** The fabric's yielding hinges and its measured stiffening, each null when the preset asks for none. */
    private HingePlasticity plasticity;
    private MeasuredStiffening stiffening;
    /** The fabric's hinges following its measured bending curve (with stiffening, when the fabric has one), or null. */
    private xpbdcloth.fabric.MeasuredBending measuredBending;
    /** The edges a fabric with a breaking strain watches ({@link Tearing}), or null: it does not tear. */
    private xpbdcloth.engine.BreakingEdges breaking;
    /** The gas (or held volume) inside the cloth, or null when the preset fills it with nothing. */
    private EnclosedGas gas;
    /** The gas's nRT as the preset filled it (J), what the gas keys pump around. */
    private double presetAmount = Double.NaN;
    /** Whether the fabric bends by dihedral hinges (a bent rest, or yielding) rather than plate patches. */
    private boolean bendsByHinges;
    /** A garment's panels' fabrics now (the preset's, until {@link #useFabric} makes them all one), or null; and {@link #cutFrom}'s text for them. */
    private Fabric[] panelFabrics;
    private String cutFrom;
    /** {@link #fabrics}, kept as the fabrics change (the HUD asks every frame). */
    private java.util.List<Fabric> fabrics = java.util.List.of();
    /** A garment's sewing, or null; and its particles' representatives once sewn ({@link xpbdcloth.pattern.PatternMesh#welded}). */
    private Sewing sewing;
    private int[] welded;

    private Scene(Preset preset) {
        this.preset = preset;
        cloth = preset.cloth.isMesh() ? meshCloth(preset) : gridCloth(preset);

        simulation = cloth.simulation(preset.solver);
        Preset.GarmentSpec garment = preset.cloth.garment;
        if (preset.fabric != null) {
            Preset.FabricSpec f = preset.fabric;
            // A garment's rest shape is its flat pattern, not the panels rolled round the body: its fabric is
            // built with each particle where it lies on its panel, then the panels go back where they start.
            double[] placed = garment == null ? null : flatten(cloth.particles(), garment.pattern.flatPositions());
            double[] warp = f.warp != null ? f.warp : FabricConstraints.warpFromTextureCoordinates(cloth.particles(), cloth.triangles(), preset.cloth.mesh.triangleUVs());
            // A stiffness that follows the curvature, as a rest angle that yields, needs the fabric's hinges dihedral.
            boolean bendingCurve = f.stiffening && f.fabric.bendingCurve != null;
            for (ConstraintBlock b : FabricConstraints.build(cloth.particles(), cloth.triangles(), warp, f.fabric.membrane, f.fabric.bendingStiffness, f.tethers,
                    f.plasticity != null || bendingCurve))
                simulation.add(b);
            if (bendingCurve) measuredBending = new xpbdcloth.fabric.MeasuredBending(simulation.blocks(), cloth.particles(), cloth.triangles(), warp, f.fabric.bendingCurve);
            if (garment != null) {
                panelFabrics = garment.panelFabrics();
                PanelFabrics.apply(simulation.blocks(), cloth.particles(), garment.pattern.panelOfVertex(), garment.pattern.panelOfTriangle(), panelFabrics);
            }
            if (placed != null) for (int i = 0; i < cloth.particles().count(); i++) cloth.particles().setPosition(i, placed[3 * i], placed[3 * i + 1], placed[3 * i + 2]);
            if (f.plasticity != null) {
                plasticity = new HingePlasticity(simulation.blocks(), cloth.particles(), f.plasticity.yieldCurvature, f.plasticity.rate);
                simulation.add(plasticity);
            }
            if (f.stiffening) {
                stiffening = new MeasuredStiffening(simulation.blocks(), f.fabric.stretchingCurve);
                simulation.add(stiffening);
            }
            if (measuredBending != null) simulation.add(measuredBending);
            if (!Double.isNaN(f.breakingStrain)) {
                breaking = new xpbdcloth.engine.BreakingEdges(cloth.particles(), cloth.triangles(), f.breakingStrain);
                simulation.add(breaking);
            }
            for (ConstraintBlock b : simulation.blocks()) bendsByHinges |= b instanceof DihedralBlock;
            fabric = f.fabric;
            noteCut();
        }
        if (garment != null) {
            xpbdcloth.pattern.PatternMesh.SeamHinges hinges = garment.pattern.seamHinges();
            // A seam between two fabrics bends as their mean.
            int[] panelOf = garment.pattern.panelOfVertex();
            double[] seamStiffness = new double[hinges.restAreaOverEdgeSquared.length];
            for (int h = 0; h < seamStiffness.length; h++)
                seamStiffness[h] = (panelFabrics[panelOf[hinges.particles[4 * h]]].bendingStiffness + panelFabrics[panelOf[hinges.particles[4 * h + 1]]].bendingStiffness) / 2;
            sewing = new Sewing(cloth.particles(), garment.pattern.allStitches(), hinges.particles, hinges.restAreaOverEdgeSquared,
                    garment.sewingTime, garment.sewingCompliance, seamStiffness, garment.seamBending);
            for (ConstraintBlock b : sewing.blocks()) simulation.add(b);
            simulation.add(sewing.weightless(simulation));
            welded = garment.pattern.welded();
        }
        if (preset.pressure != null) {
            gas = preset.pressure.fill(cloth.particles(), cloth.triangles());
            presetAmount = gas.amount();
            simulation.add(gas);
        }
        if (preset.aerodynamics != null) {
            Preset.AerodynamicsSpec a = preset.aerodynamics;
            simulation.add(new Aerodynamics(cloth.triangles(), a.density, a.drag, a.lift).air(a.air[0], a.air[1], a.air[2]));
        }

        for (Preset.PlaneSpec pl : preset.planes) {
            Plane plane = new Plane(pl.point, pl.normal, pl.margin, pl.staticFriction, pl.kineticFriction);
            plane.depenetrationSpeed(pl.depenetrationSpeed);
            simulation.add(plane);
        }
        if (preset.selfCollision != null) simulation.selfCollision(selfCollision(cloth, preset.selfCollision, garment));
        for (Preset.SolidSpec sp : preset.solids) {
            RigidCollider solid = sp.type.equals("box")
                    ? new Box(path(sp.path), sp.halfExtents, sp.rotation, sp.margin, sp.staticFriction, sp.kineticFriction)
                    : new Capsule(path(sp.path), sp.axis, sp.halfLength, sp.radius, sp.margin, sp.staticFriction, sp.kineticFriction);
            solid.depenetrationSpeed(sp.depenetrationSpeed);
            simulation.add(solid.spin(sp.angularVelocity[0], sp.angularVelocity[1], sp.angularVelocity[2]));
        }
        for (Preset.BodySpec b : preset.bodies) {
            MeshCollider body = new MeshCollider(path(b.path), b.mesh.vertices, b.mesh.triangles, b.mesh.frames, b.mesh.fps, b.loop, b.start, b.margin, b.staticFriction, b.kineticFriction);
            body.depenetrationSpeed(b.depenetrationSpeed);
            simulation.add(body.spin(b.angularVelocity[0], b.angularVelocity[1], b.angularVelocity[2]));
        }
        for (Preset.SphereSpec sp : preset.spheres) {
            Sphere sphere = new Sphere(path(sp), sp.radius, sp.margin, sp.staticFriction, sp.kineticFriction)
                    .spin(sp.angularVelocity[0], sp.angularVelocity[1], sp.angularVelocity[2]);
            sphere.depenetrationSpeed(sp.depenetrationSpeed);
            simulation.add(sphere);
        }

        double end = 0;
        if (!preset.pinMotions.isEmpty()) {
            PinScript script = new PinScript(cloth.particles(), preset.pinMotions);
            simulation.add(script);
            end = script.endTime();
        }
        scriptEnd = end;

        Preset.WindSpec w = preset.wind;
        wind = w == null
                ? new Wind(cloth.triangles(), 2, 0, 1.5, 0.5, 0.3)
                : new Wind(cloth.triangles(), w.velocity[0], w.velocity[1], w.velocity[2], w.drag, w.gust);
        setWind(w != null);
    }

    private static Cloth gridCloth(Preset preset) {
        Preset.Cloth c = preset.cloth;
        ClothBuilder b = new ClothBuilder().resolution(c.columns, c.rows).size(c.width, c.height).plane(c.plane)
                .origin(c.origin[0], c.origin[1], c.origin[2]).families(preset.families);
        if (Double.isNaN(c.totalMass)) b.arealDensity(c.arealDensity);
        else b.totalMass(c.totalMass);
        for (int[] pin : c.pins) b.pin(pin[0], pin[1]);
        return b.build();
    }

    private static Cloth meshCloth(Preset preset) {
        Preset.Cloth c = preset.cloth;
        MeshClothBuilder b = new MeshClothBuilder(c.mesh).families(preset.families);
        if (Double.isNaN(c.totalMass)) b.arealDensity(c.arealDensity);
        else b.totalMass(c.totalMass);
        b.pin(c.pinnedVertices);
        return b.build();
    }

    /** Builds a fresh scene from a preset (the preset is already validated). */
    public static Scene of(Preset preset) {
        if (preset == null) throw new IllegalArgumentException("preset must not be null, was null");
        try {
            return new Scene(preset);
        } catch (PresetException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            // What only the engine can check (a mesh it cannot build, say) still names the file.
            throw new PresetException(preset.source, "(building the scene)", e.getMessage());
        }
    }

    /**
     * The cloth's self-collision from its rest mesh; a garment's as it will be once sewn (each stitched particle
     * where its partner is, so the two sides of a seam are neighbours, not a contact that holds the seam open).
     */
    public static SelfCollision selfCollision(Cloth cloth, Preset.SelfCollisionSpec s, Preset.GarmentSpec garment) {
        int[] triangles = s.continuous && cloth.triangles().length > 0 ? cloth.triangles() : null;
        double[] rest = cloth.mesh().positions();
        int[] welded = garment == null ? null : garment.pattern.welded();
        if (welded != null) for (int i = 0; i < welded.length; i++) System.arraycopy(rest, 3 * welded[i], rest, 3 * i, 3);
        SelfCollision self = new SelfCollision(rest, triangles, welded, s.thickness, s.staticFriction, s.kineticFriction);
        if (s.pointTriangle && cloth.triangles().length > 0) self.withPointTriangle(cloth.triangles());
        return s.untangle && cloth.triangles().length > 0 ? self.untangling(cloth.triangles()) : self;
    }

    /** Puts each particle at its flat pattern position (x, y, 0); returns where they were. */
    private static double[] flatten(xpbdcloth.engine.Particles p, double[] flat) {
        double[] placed = p.positions().clone();
        for (int i = 0; i < p.count(); i++) p.setPosition(i, flat[2 * i], flat[2 * i + 1], 0);
        return placed;
    }

    /**
     * How many pairs of the cloth's triangles pass through each other now ({@link TriangleIntersections}, the
     * measure self-collision must hold at 0); a garment's stitched particles count as one, so triangles that
     * meet across a seam are neighbours, not a crossing.
     */
    public int crossingPairs() {
        return TriangleIntersections.count(simulation.particles().positions(), cloth.triangles(), sewing == null ? null : welded);
    }

    /** A garment's sewing (its stitches and seams), or null for any other cloth. */
    public Sewing sewing() { return sewing; }

    /** A built-in scene by name. */
    public static Scene builtIn(String name) { return of(PresetLoader.builtIn(name)); }

    static SpherePath path(Preset.SphereSpec s) { return path(new Preset.PathSpec(s.path, s.centre, s.vector, s.pathRadius, s.rate)); }

    static SpherePath path(Preset.PathSpec s) {
        double[] c = s.centre, v = s.vector;
        switch (s.type) {
            case "linear": return SpherePath.linear(c[0], c[1], c[2], v[0], v[1], v[2]);
            case "circle": return SpherePath.circle(c[0], c[1], c[2], s.radius, s.rate);
            case "oscillation": return SpherePath.oscillation(c[0], c[1], c[2], v[0], v[1], v[2], s.rate);
            case "fixed": return SpherePath.fixed(c[0], c[1], c[2]);
            default: throw new IllegalArgumentException("path.type must be fixed, linear, circle or oscillation, was " + s.type);
        }
    }

    public Preset preset() { return preset; }

    /** The fabric the cloth is now, or null for a cloth of springs. */
    public Fabric fabric() { return fabric; }

    /**
     * Makes the running cloth another fabric (no reset: shape, motion and pins stay; moduli, bending and
     * areal density change). A cloth of springs has no membrane to change and is refused.
     */
    public void useFabric(Fabric next) {
        if (fabric == null) throw new IllegalArgumentException("fabric: this cloth is springs, not a fabric (its preset has no \"fabric\" block)");
        if (panelFabrics != null) {
            java.util.Arrays.fill(panelFabrics, next);
            Preset.GarmentSpec garment = preset.cloth.garment;
            PanelFabrics.apply(simulation.blocks(), cloth.particles(), garment.pattern.panelOfVertex(), garment.pattern.panelOfTriangle(), panelFabrics);
        } else FabricSwap.apply(simulation.blocks(), cloth.particles(), next);
        if (stiffening != null) stiffening.use(next.stretchingCurve);
        if (measuredBending != null) measuredBending.use(next.bendingCurve);
        if (sewing != null) sewing.useBendingStiffness(next.bendingStiffness);
        fabric = next;
        noteCut();
    }

    /**
     * The fabrics the cloth is cut from now, each once, in the pattern's order: a garment's panels' (until
     * {@link #useFabric} makes them one), or the one fabric of any other cloth; empty for a cloth of springs.
     */
    public java.util.List<Fabric> fabrics() { return fabrics; }

    /**
     * Which panels of a garment of several fabrics are cut from which, in the pattern's order ("tablecloth
     * (top), denim (front border, right border)"); null when the cloth is one fabric.
     */
    public String cutFrom() { return cutFrom; }

    /** Sets {@link #fabrics} and {@link #cutFrom} from the fabric and the panels' fabrics now. */
    private void noteCut() {
        if (panelFabrics == null) {
            fabrics = java.util.List.of(fabric);
            return;
        }
        java.util.List<Fabric> each = new java.util.ArrayList<>();
        for (Fabric f : panelFabrics) if (!each.contains(f)) each.add(f);
        fabrics = java.util.Collections.unmodifiableList(each);
        cutFrom = describeCut();
    }

    private String describeCut() {
        java.util.Map<String, java.util.List<String>> panelsOf = new java.util.LinkedHashMap<>();
        java.util.List<xpbdcloth.pattern.Panel> panels = preset.cloth.garment.pattern.pattern.panels();
        for (int i = 0; i < panelFabrics.length; i++) panelsOf.computeIfAbsent(panelFabrics[i].name, k -> new java.util.ArrayList<>()).add(panels.get(i).name);
        if (panelsOf.size() < 2) return null;
        java.util.StringJoiner out = new java.util.StringJoiner(", ");
        panelsOf.forEach((fabricName, names) -> out.add(fabricName + " (" + String.join(", ", names) + ")"));
        return out.toString();
    }

    /** The gas (or held volume) inside the cloth, or null. */
    public EnclosedGas gas() { return gas; }

    /** How far the gas keys pump from the preset's amount: a thousandth to a thousand times it. */
    static final double PUMP_RANGE = 1e3;

    /**
     * Pumps gas in (factor > 1) or lets it out: nRT times the factor, within {@link #PUMP_RANGE} of the preset's
     * amount, or a held volume within the presets' volume ratios (a change that would leave them is not made).
     * Returns whether it changed; false for a cloth with nothing inside.
     */
    public boolean inflate(double factor) {
        if (gas == null) return false;
        if (gas.isGas()) {
            double next = gas.amount() * factor, from = presetAmount;
            if (!(next >= from / PUMP_RANGE && next <= from * PUMP_RANGE && next <= EnclosedGas.MAX_AMOUNT)) return false;
            gas.setAmount(next);
        } else {
            double next = gas.targetVolume() * factor;
            if (!(next >= Limits.VOLUME_RATIO.lo * gas.restVolume() && next <= Limits.VOLUME_RATIO.hi * gas.restVolume())) return false;
            gas.setTargetVolume(next);
        }
        return true;
    }

    /** How the fabric bends, in words: plate patches on a flat rest, dihedral hinges where it is bent or may yield. */
    public String bendingModel() {
        if (plasticity != null) return String.format(Locale.ROOT, "dihedral hinges yielding past %.3g/m (a crease)", plasticity.yieldCurvature());
        if (measuredBending != null) return "dihedral hinges following the measured bending curve";
        return bendsByHinges ? "dihedral hinges (a bent rest)" : "the plate's on every triangle";
    }
    public Cloth cloth() { return cloth; }

    /** The edges watched for tearing, or null when the fabric has no breaking strain. */
    public xpbdcloth.engine.BreakingEdges breaking() { return breaking; }

    /** Whether the last step broke an edge, so the scene to go on with is {@link #torn()}. */
    public boolean tearing() { return breaking != null && breaking.broke(); }

    /**
     * This scene cut where the last step broke an edge ({@link Tearing}): a new scene, carrying on from this
     * one's state, which is closed; or this scene itself when nothing broke or no cut could be made.
     */
    public Scene torn() { return tearing() ? Tearing.torn(this) : this; }

    /** One step, and the scene to go on with: this one, or this one {@link #torn()} where the step broke an edge. */
    public Scene step() {
        simulation.step();
        return torn();
    }

    /** A material that follows the cloth's state takes it now (a scene that carries on from another's state). */
    void followState() {
        if (stiffening != null) stiffening.afterStep(cloth.particles(), simulation.settings().timestep());
        if (measuredBending != null) measuredBending.afterStep(cloth.particles(), simulation.settings().timestep());
    }
    public Simulation simulation() { return simulation; }
    public Wind wind() { return wind; }
    public boolean windOn() { return windOn; }

    /** Time (s) after which the scripted pins hold still; 0 if none move. */
    public double scriptEnd() { return scriptEnd; }

    public void setWind(boolean on) {
        if (on == windOn) return;
        if (on) simulation.add(wind);
        else simulation.remove(wind);
        windOn = on;
    }
}
