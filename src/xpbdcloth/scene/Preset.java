package xpbdcloth.scene;

import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import xpbdcloth.engine.ClothBuilder;
import xpbdcloth.engine.ConstraintFamily;
import xpbdcloth.engine.Material;
import xpbdcloth.engine.SolverSettings;
import xpbdcloth.mesh.ClothMesh;

/**
 * Everything a scene is made of, as read from a preset file by {@link PresetLoader}: the cloth, its
 * constraint families, the solver, kinematic spheres, scripted pins and wind. Immutable and already
 * validated; units are SI (m, s, kg, N, rad).
 */
public final class Preset {
    public final String name;
    public final String description;
    /** The file it was read from (or the built-in's name), for messages. */
    public final String source;
    public final Cloth cloth;
    /** k and α per family; a family absent here is not built. */
    public final Map<ConstraintFamily, Material> families;
    /** The solver section, as the engine takes it. */
    public final SolverSettings solver;
    public final List<SphereSpec> spheres;
    /** Fixed planes: floors, walls, slopes. */
    public final List<PlaneSpec> planes;
    /** Boxes and capsules. */
    public final List<SolidSpec> solids;
    /** Triangle meshes to collide with (still, animated, or on a rigid path). */
    public final List<BodySpec> bodies;
    /** The cloth's contacts with itself, or null when it passes through itself. */
    public final SelfCollisionSpec selfCollision;
    public final List<PinMotion> pinMotions;
    /** Null when the preset has no wind. */
    public final WindSpec wind;
    /** The cloth as a material (membrane, dihedral bending, tethers), or null for the spring families alone. */
    public final FabricSpec fabric;
    /** Quadratic drag and lift in moving air, or null. */
    public final AerodynamicsSpec aerodynamics;
    /** The gas (or the held volume) inside a closed cloth, or null. */
    public final PressureSpec pressure;

    Preset(String source, String name, String description, Cloth cloth, Map<ConstraintFamily, Material> families, SolverSettings solver,
           List<SphereSpec> spheres, List<PlaneSpec> planes, List<SolidSpec> solids, List<BodySpec> bodies, SelfCollisionSpec selfCollision, List<PinMotion> pinMotions, WindSpec wind,
           FabricSpec fabric, AerodynamicsSpec aerodynamics, PressureSpec pressure) {
        this.source = source;
        this.name = name;
        this.description = description;
        this.cloth = cloth;
        EnumMap<ConstraintFamily, Material> own = new EnumMap<>(ConstraintFamily.class);  // EnumMap(Map) refuses an empty map that is not one
        own.putAll(families);
        this.families = Collections.unmodifiableMap(own);
        this.solver = solver;
        this.spheres = Collections.unmodifiableList(spheres);
        this.planes = Collections.unmodifiableList(planes);
        this.solids = Collections.unmodifiableList(solids);
        this.bodies = Collections.unmodifiableList(bodies);
        this.selfCollision = selfCollision;
        this.pinMotions = Collections.unmodifiableList(pinMotions);
        this.wind = wind;
        this.fabric = fabric;
        this.aerodynamics = aerodynamics;
        this.pressure = pressure;
    }

    /**
     * What fills a closed cloth: a gas given by its pressure over the air at the rest shape (gauge, Pa) or by its
     * amount (moles at a temperature), with the air outside (ambient, Pa); or a volume held at a multiple of
     * the rest volume. Exactly one of gauge, moles and volumeRatio is a number, the others NaN.
     */
    public static final class PressureSpec {
        public final double gauge, moles, temperature, volumeRatio, ambient;

        PressureSpec(double gauge, double moles, double temperature, double volumeRatio, double ambient) {
            this.gauge = gauge; this.moles = moles; this.temperature = temperature; this.volumeRatio = volumeRatio; this.ambient = ambient;
        }

        /** The gas (or held volume) this asks for, in the closed surface of these particles' triangles. */
        public xpbdcloth.engine.EnclosedGas fill(xpbdcloth.engine.Particles rest, int[] triangles) {
            if (!Double.isNaN(gauge)) return xpbdcloth.engine.EnclosedGas.ofGauge(rest, triangles, gauge, ambient);
            if (!Double.isNaN(moles)) return xpbdcloth.engine.EnclosedGas.ofGas(rest, triangles, moles * xpbdcloth.engine.EnclosedGas.GAS_CONSTANT * temperature, ambient);
            return xpbdcloth.engine.EnclosedGas.ofHeldVolume(rest, triangles, volumeRatio);
        }
    }

    /**
     * A triangle mesh to collide with: the file's body as placed, when its frames start to play (s) and whether
     * they loop, friction, and a rigid path and spin.
     */
    public static final class BodySpec {
        public final String file;
        public final xpbdcloth.mesh.BodyMesh mesh;
        public final double start;
        public final boolean loop;
        public final double margin, staticFriction, kineticFriction, depenetrationSpeed;
        public final double[] angularVelocity;
        public final PathSpec path;

        BodySpec(String file, xpbdcloth.mesh.BodyMesh mesh, double start, boolean loop, double margin, double staticFriction, double kineticFriction, double[] angularVelocity, PathSpec path,
                 double depenetrationSpeed) {
            this.file = file; this.mesh = mesh; this.start = start; this.loop = loop; this.margin = margin; this.staticFriction = staticFriction;
            this.kineticFriction = kineticFriction; this.angularVelocity = angularVelocity; this.path = path; this.depenetrationSpeed = depenetrationSpeed;
        }
    }

    /** Air of density ρ (kg/m³) moving at a velocity (m/s), and a flat plate's drag and lift coefficients. */
    public static final class AerodynamicsSpec {
        public final double density, drag, lift;
        public final double[] air;

        AerodynamicsSpec(double density, double drag, double lift, double[] air) {
            this.density = density; this.drag = drag; this.lift = lift; this.air = air.clone();
        }
    }

    /**
     * A cloth as a fabric: the material (moduli per unit width in N/m, ν₁₂, bending stiffness in N·m, and
     * an areal density when it comes from the catalogue), the warp direction in scene coordinates, and
     * whether free particles are tethered to their nearest pin.
     */
    public static final class FabricSpec {
        public final xpbdcloth.fabric.Fabric fabric;
        /** The warp direction, or null: then each triangle's from the mesh's texture coordinates (u grows along the warp). */
        public final double[] warp;
        public final boolean tethers;
        /** Bending that yields, or null (elastic). */
        public final PlasticitySpec plasticity;
        /** Whether the membrane follows the fabric's measured stretching curve (else it is linear, the curve's slope at zero). */
        public final boolean stiffening;
        /** The edge strain past which the cloth tears ({@link Tearing}), or NaN: it does not. */
        public final double breakingStrain;

        FabricSpec(xpbdcloth.fabric.Fabric fabric, double[] warp, boolean tethers, PlasticitySpec plasticity, boolean stiffening) {
            this(fabric, warp, tethers, plasticity, stiffening, Double.NaN);
        }

        FabricSpec(xpbdcloth.fabric.Fabric fabric, double[] warp, boolean tethers, PlasticitySpec plasticity, boolean stiffening, double breakingStrain) {
            this.fabric = fabric; this.warp = warp == null ? null : warp.clone(); this.tethers = tethers; this.plasticity = plasticity;
            this.stiffening = stiffening;
            this.breakingStrain = breakingStrain;
        }
    }

    /**
     * A garment: its pattern meshed (panels placed around the body, their flat rest shape, the stitches), the
     * fabric it is cut from, and how it is sewn: the sewing time (s), the stitches' compliance while sewing
     * (m/N), and the seams' bending stiffness over the fabric's once closed.
     */
    public static final class GarmentSpec {
        public final xpbdcloth.pattern.PatternMesh pattern;
        /** The garment's fabric: the preset's if it gives one, else its first panel's. */
        public final FabricSpec fabric;
        /** Each panel's fabric, in the pattern's order: the preset's for all if it gives one, else each panel's own. */
        private final xpbdcloth.fabric.Fabric[] panelFabrics;
        public final double sewingTime, sewingCompliance, seamBending;

        GarmentSpec(xpbdcloth.pattern.PatternMesh pattern, FabricSpec fabric, xpbdcloth.fabric.Fabric[] panelFabrics, double sewingTime, double sewingCompliance, double seamBending) {
            this.pattern = pattern; this.fabric = fabric; this.panelFabrics = panelFabrics.clone();
            this.sewingTime = sewingTime; this.sewingCompliance = sewingCompliance; this.seamBending = seamBending;
        }

        public xpbdcloth.fabric.Fabric[] panelFabrics() { return panelFabrics.clone(); }
    }

    /** A bend sharper than the yield curvature (1/m) moves its rest angle at the rate (1/s): a crease ({@link xpbdcloth.engine.HingePlasticity}). */
    public static final class PlasticitySpec {
        public final double yieldCurvature, rate;

        PlasticitySpec(double yieldCurvature, double rate) { this.yieldCurvature = yieldCurvature; this.rate = rate; }
    }

    /**
     * The cloth: a grid (resolution, size in m, plane, origin in m, pinned (row, col) pairs) or a mesh
     * (loaded, welded and placed; pinned vertex indices), and its mass.
     */
    public static final class Cloth {
        /** Grid only (0 for a mesh). */
        public final int columns, rows;
        public final double width, height;
        public final ClothBuilder.Plane plane;
        public final double[] origin;
        /** Exactly one of these is finite. */
        public final double arealDensity, totalMass;
        /** Grid only: pinned (row, col). */
        public final List<int[]> pins;
        /** Mesh only (null for a grid): the mesh in scene coordinates, and where it came from. */
        public final ClothMesh mesh;
        public final String meshFile;
        /** Mesh only: pinned vertex indices, ascending, each once. */
        public final int[] pinnedVertices;
        /** A garment's panels and sewing (its mesh is {@link #mesh}), or null. */
        public final GarmentSpec garment;

        Cloth(int columns, int rows, double width, double height, ClothBuilder.Plane plane, double[] origin,
              double arealDensity, double totalMass, List<int[]> pins) {
            this.columns = columns; this.rows = rows; this.width = width; this.height = height;
            this.plane = plane; this.origin = origin; this.arealDensity = arealDensity; this.totalMass = totalMass;
            this.pins = Collections.unmodifiableList(pins);
            this.mesh = null;
            this.meshFile = null;
            this.pinnedVertices = new int[0];
            this.garment = null;
        }

        Cloth(ClothMesh mesh, String meshFile, double arealDensity, double totalMass, int[] pinnedVertices) {
            this(mesh, meshFile, arealDensity, totalMass, pinnedVertices, null);
        }

        Cloth(ClothMesh mesh, String meshFile, double arealDensity, double totalMass, int[] pinnedVertices, GarmentSpec garment) {
            this.columns = 0; this.rows = 0; this.width = 0; this.height = 0; this.plane = null; this.origin = new double[3];
            this.arealDensity = arealDensity; this.totalMass = totalMass; this.pins = List.of();
            this.mesh = mesh;
            this.meshFile = meshFile;
            this.pinnedVertices = pinnedVertices.clone();
            this.garment = garment;
        }

        public boolean isMesh() { return mesh != null; }

        /** The shortest edge between particles at rest, m: a grid's spacing, or a mesh's shortest triangle side. */
        public double shortestEdge() {
            if (!isMesh()) {
                double dx = columns > 1 ? width / (columns - 1) : Double.POSITIVE_INFINITY, dy = rows > 1 ? height / (rows - 1) : Double.POSITIVE_INFINITY;
                return Math.min(dx, dy);
            }
            return mesh.shortestEdge();
        }

        /** The particle a pin motion names: (row, col) on a grid. */
        int vertex(int row, int col) { return row * columns + col; }
    }

    /** A fixed plane collider: a point of its surface and the normal of the side the cloth stays on. */
    public static final class PlaneSpec {
        public final double[] point, normal;
        public final double margin, staticFriction, kineticFriction, depenetrationSpeed;

        PlaneSpec(double[] point, double[] normal, double margin, double staticFriction, double kineticFriction, double depenetrationSpeed) {
            this.point = point; this.normal = normal; this.margin = margin;
            this.staticFriction = staticFriction; this.kineticFriction = kineticFriction; this.depenetrationSpeed = depenetrationSpeed;
        }
    }

    /** The cloth's thickness against itself (m) and the friction between its layers. */
    public static final class SelfCollisionSpec {
        public final double thickness, staticFriction, kineticFriction;
        /** Whether the triangles are kept from passing through each other in a substep (a CrossingGuard), not only the particles apart. */
        public final boolean continuous;
        /** Whether a cloth found passed through itself at a step's end is put back (a CrossingUntangler). */
        public final boolean untangle;
        /** Whether each vertex is kept the thickness from the cloth's faces too, not only from its particles (PointTriangleContacts). */
        public final boolean pointTriangle;

        public SelfCollisionSpec(double thickness, double staticFriction, double kineticFriction, boolean continuous, boolean untangle, boolean pointTriangle) {
            this.thickness = thickness; this.staticFriction = staticFriction; this.kineticFriction = kineticFriction;
            this.continuous = continuous;
            this.untangle = untangle;
            this.pointTriangle = pointTriangle;
        }
    }

    /** Where a kinematic collider's centre goes: fixed, linear, circle or oscillation. */
    public static final class PathSpec {
        public final String type;
        /** fixed: centre; linear: start; circle and oscillation: centre. */
        public final double[] centre;
        /** linear: velocity (m/s); oscillation: amplitude (m). */
        public final double[] vector;
        /** circle: radius (m). */
        public final double radius;
        /** circle: angular speed (rad/s); oscillation: frequency (Hz). */
        public final double rate;

        PathSpec(String type, double[] centre, double[] vector, double radius, double rate) {
            this.type = type; this.centre = centre; this.vector = vector; this.radius = radius; this.rate = rate;
        }
    }

    /**
     * A kinematic box (half extents, rotation in degrees about x, y, z) or capsule (axis, half length,
     * radius), its path and spin.
     */
    public static final class SolidSpec {
        /** "box" or "capsule". */
        public final String type;
        /** box: half extents (m) and rotation (degrees); null for a capsule. */
        public final double[] halfExtents, rotation;
        /** capsule: axis direction; null for a box. */
        public final double[] axis;
        /** capsule: half length between its caps' centres and radius (m). */
        public final double halfLength, radius;
        public final double margin, staticFriction, kineticFriction, depenetrationSpeed;
        public final double[] angularVelocity;
        public final PathSpec path;

        SolidSpec(String type, double[] halfExtents, double[] rotation, double[] axis, double halfLength, double radius,
                  double margin, double staticFriction, double kineticFriction, double[] angularVelocity, PathSpec path, double depenetrationSpeed) {
            this.type = type; this.halfExtents = halfExtents; this.rotation = rotation; this.axis = axis;
            this.halfLength = halfLength; this.radius = radius; this.margin = margin; this.staticFriction = staticFriction;
            this.kineticFriction = kineticFriction; this.angularVelocity = angularVelocity; this.path = path; this.depenetrationSpeed = depenetrationSpeed;
        }

        /** The largest distance from the centre to the solid's surface, m. */
        public double extent() {
            return halfExtents != null ? Math.sqrt(halfExtents[0] * halfExtents[0] + halfExtents[1] * halfExtents[1] + halfExtents[2] * halfExtents[2])
                    : halfLength + radius;
        }
    }

    /** A kinematic sphere and its path: fixed, linear, circle or oscillation. */
    public static final class SphereSpec {
        public final double radius, margin, staticFriction, kineticFriction, depenetrationSpeed;
        public final double[] angularVelocity;
        public final String path;
        /** fixed: centre; linear: start; circle and oscillation: centre. */
        public final double[] centre;
        /** linear: velocity (m/s); oscillation: amplitude (m). */
        public final double[] vector;
        /** circle: radius (m). */
        public final double pathRadius;
        /** circle: angular speed (rad/s); oscillation: frequency (Hz). */
        public final double rate;

        SphereSpec(double radius, double margin, double staticFriction, double kineticFriction, double[] angularVelocity,
                   String path, double[] centre, double[] vector, double pathRadius, double rate, double depenetrationSpeed) {
            this.depenetrationSpeed = depenetrationSpeed;
            this.radius = radius; this.margin = margin; this.staticFriction = staticFriction;
            this.kineticFriction = kineticFriction; this.angularVelocity = angularVelocity; this.path = path;
            this.centre = centre; this.vector = vector; this.pathRadius = pathRadius; this.rate = rate;
        }
    }

    /** A pinned particle (vertex index) moved by displacement (m) over [start, start + duration] s, eased, then held. */
    public static final class PinMotion {
        public final int vertex;
        /** m (zeros when the motion only turns). */
        public final double[] displacement;
        public final double start, duration;
        /** The turn: a unit axis and a centre (m) it passes through, and its angle (rad, 0 for none). */
        public final double[] axis, centre;
        public final double angle;

        PinMotion(int vertex, double[] displacement, double start, double duration, double[] axis, double[] centre, double angle) {
            this.vertex = vertex; this.displacement = displacement; this.start = start; this.duration = duration;
            this.axis = axis; this.centre = centre; this.angle = angle;
        }
    }

    /** Wind velocity (m/s), drag coefficient (kg/(m²·s)) and gust strength ∈ [0, 1]. */
    public static final class WindSpec {
        public final double[] velocity;
        public final double drag, gust;

        WindSpec(double[] velocity, double drag, double gust) {
            this.velocity = velocity; this.drag = drag; this.gust = gust;
        }
    }
}
