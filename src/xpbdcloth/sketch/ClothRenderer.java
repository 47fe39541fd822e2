package xpbdcloth.sketch;

import processing.core.PConstants;
import processing.core.PGraphics;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.ConstraintBlock;
import xpbdcloth.engine.DistanceBlock;
import xpbdcloth.engine.Particles;
import xpbdcloth.engine.Plane;
import xpbdcloth.engine.RigidCollider;
import xpbdcloth.engine.SelfCollision;
import xpbdcloth.engine.Simulation;
import xpbdcloth.engine.Sphere;
import xpbdcloth.mesh.VertexNormals;
import xpbdcloth.scene.Scene;

/**
 * Draws scenes in world coordinates (after {@link OrbitCamera#apply}): the cloth as a lit, smooth-shaded
 * two-sided triangle mesh, or as a wireframe coloured by strain; particles, spheres with a spin marking,
 * and a ground grid. Normals are recomputed each frame into arrays kept between frames, so drawing
 * allocates nothing per vertex.
 */
public final class ClothRenderer {
    /** Front and back colours of the cloth (RGB). */
    static final int[] FRONT = {88, 148, 222}, BACK = {236, 172, 92};
    /** The colliders' colour (RGB): glazed ceramic, drawn with a specular highlight. */
    static final int[] COLLIDER = {214, 206, 192};
    /** Strain at which the wireframe is fully red (stretched) or blue (compressed). */
    static final double FULL_COLOUR_STRAIN = 0.05;

    private double[] normals = new double[0];
    /**
     * P3D multiplies stroke weights by the modelview's scale: a caller that draws the world scaled by s
     * (the library, in pixels per metre) sets 1/s here so lines and points keep their widths in pixels.
     */
    private float strokeUnit = 1;

    public void strokeUnit(float unit) { strokeUnit = unit; }
    private final FoldShading folds = new FoldShading();

    /** Area-weighted vertex normals, into an array kept between frames. */
    private void computeNormals(Cloth cloth) {
        double[] x = cloth.particles().positions();
        if (normals.length != x.length) normals = new double[x.length];
        VertexNormals.compute(x, cloth.triangles(), normals);
    }

    /**
     * The mesh, lit on both sides: each triangle whose face turns away from the eye is drawn in the back
     * colour. Its normals are not flipped: P3D lights both sides itself (its shaders light a face that
     * OpenGL finds turned away with the negated normal), so a flip here would light the back side from
     * the wrong side.
     */
    void drawMesh(PGraphics g, Cloth cloth, double eyeX, double eyeY, double eyeZ) {
        computeNormals(cloth);
        boolean[] dark = checker(cloth);
        double[] x = cloth.particles().positions();
        int[] t = cloth.triangles();
        folds.compute(x, t, normals);
        g.noStroke();
        g.specular(0); // fabric is matte; the colliders shine
        g.shininess(1);
        g.beginShape(PConstants.TRIANGLES);
        for (int k = 0; k < t.length; k += 3) {
            int a = 3 * t[k], b = 3 * t[k + 1], c = 3 * t[k + 2];
            double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            boolean front = nx * (eyeX - x[a]) + ny * (eyeY - x[a + 1]) + nz * (eyeZ - x[a + 2]) >= 0;
            int[] col = front ? FRONT : BACK;
            float[] light = front ? folds.front : folds.back;
            float shade = dark[k / 3] ? CHECKER_SHADE : 1;
            vertex(g, x, a, shade * light[t[k]], col);
            vertex(g, x, b, shade * light[t[k + 1]], col);
            vertex(g, x, c, shade * light[t[k + 2]], col);
        }
        g.endShape();
    }

    /**
     * Every running scene of the state in world coordinates (the pair side by side): the cloth as the
     * state's view asks (mesh, wireframe or rope), its particles and its colliders. The eye is the
     * camera's position in the same coordinates, so each triangle is lit on the side the viewer sees.
     */
    public void drawScenes(PGraphics g, SketchState state, double eyeX, double eyeY, double eyeZ) {
        java.util.List<Scene> running = state.running();
        for (int i = 0; i < running.size(); i++) {
            Scene sc = running.get(i);
            double ox = state.offsetX(i);
            g.pushMatrix();
            g.translate((float) ox, 0, 0);
            if (state.wireframe) drawWireframe(g, sc);
            else if (sc.cloth().triangles().length == 0) drawRope(g, sc.cloth());
            else drawMesh(g, sc.cloth(), eyeX - ox, eyeY, eyeZ);
            drawParticles(g, sc.cloth().particles(), state.showParticles);
            if (state.showParticles) drawContacts(g, sc.simulation());
            if (state.showSpheres) for (Sphere s : sc.simulation().spheres()) drawSphere(g, s);
            if (state.showSpheres) for (Plane pl : sc.simulation().planes()) if (!(floorShown && isFloor(pl))) drawPlane(g, pl, sc.cloth());
            if (state.showSpheres) for (RigidCollider s : sc.simulation().solids()) drawSolid(g, s);
            if (i == 0 && state.fit() != null) drawGhost(g, state.fit());
            g.popMatrix();
        }
    }

    /** The observed shape a fit is matching, as a pale wireframe. */
    void drawGhost(PGraphics g, LiveFit fit) {
        double[] x = fit.observed;
        int[] e = fit.edges;
        g.strokeWeight(1.2f * strokeUnit);
        g.stroke(235, 235, 255, 150);
        g.beginShape(PConstants.LINES);
        for (int k = 0; k < e.length; k += 2) {
            int a = 3 * e[k], b = 3 * e[k + 1];
            g.vertex((float) x[a], (float) x[a + 1], (float) x[a + 2]);
            g.vertex((float) x[b], (float) x[b + 1], (float) x[b + 2]);
        }
        g.endShape();
    }

    /** Squares across the cloth's longer side, and how much darker every second one is. */
    static final int CHECKER_SQUARES = 12;
    static final float CHECKER_SHADE = 0.8f;
    private Cloth checkerFor;
    private boolean[] checkerDark;

    /**
     * A checker printed on the cloth at rest, per triangle: the squares deform with the cloth, so stretch
     * and shear show where the smooth shading alone hides them. Squares are laid in the rest mesh's two
     * widest directions (a grid's rows and columns); computed once per cloth.
     */
    private boolean[] checker(Cloth cloth) {
        if (checkerFor == cloth) return checkerDark;
        xpbdcloth.mesh.ClothMesh m = cloth.mesh();
        double[] lo = {m.min(0), m.min(1), m.min(2)}, hi = {m.max(0), m.max(1), m.max(2)};
        int thin = 0;
        for (int d = 1; d < 3; d++) if (hi[d] - lo[d] < hi[thin] - lo[thin]) thin = d;
        int u = thin == 0 ? 1 : 0, v = thin == 2 ? 1 : 2;
        double cellU = Math.max(Math.max(hi[u] - lo[u], hi[v] - lo[v]) / CHECKER_SQUARES, 1e-9), cellV = cellU;
        if (cloth.isGrid() && cloth.columns() > 1 && cloth.rows() > 1) {
            // Whole quads per square, so the squares' sides run along the threads instead of zigzagging.
            int quads = Math.max(1, Math.round((Math.max(cloth.columns(), cloth.rows()) - 1) / (float) CHECKER_SQUARES));
            cellU = Math.max(quads * (hi[u] - lo[u]) / (cloth.columns() - 1), 1e-9);
            cellV = Math.max(quads * (hi[v] - lo[v]) / (cloth.rows() - 1), 1e-9);
        }
        int[] t = cloth.triangles();
        boolean[] dark = new boolean[t.length / 3];
        for (int k = 0; k < t.length; k += 3) {
            double cu = 0, cv = 0;
            for (int j = 0; j < 3; j++) {
                double[] p = {m.x(t[k + j]), m.y(t[k + j]), m.z(t[k + j])};
                cu += (p[u] - lo[u]) / 3;
                cv += (p[v] - lo[v]) / 3;
            }
            dark[k / 3] = (((long) Math.floor(cu / cellU) + (long) Math.floor(cv / cellV)) & 1) == 1;
        }
        checkerFor = cloth;
        checkerDark = dark;
        return dark;
    }

    /** A cloth without triangles (a rope, one particle wide) as a thick polyline through its particles. */
    void drawRope(PGraphics g, Cloth cloth) {
        double[] x = cloth.particles().positions();
        g.noFill();
        g.stroke(FRONT[0], FRONT[1], FRONT[2]);
        g.strokeWeight(5 * strokeUnit);
        g.beginShape();
        for (int i = 0; i < cloth.particles().count(); i++) g.vertex((float) x[3 * i], (float) x[3 * i + 1], (float) x[3 * i + 2]);
        g.endShape();
    }

    /** Vertex k/3 with its normal (flipped for the back), in colour col darkened by shade. */
    private void vertex(PGraphics g, double[] x, int k, float shade, int[] col) {
        g.fill(shade * col[0], shade * col[1], shade * col[2]);
        g.normal((float) normals[k], (float) normals[k + 1], (float) normals[k + 2]);
        g.vertex((float) x[k], (float) x[k + 1], (float) x[k + 2]);
    }

    private final float[] rgb = new float[3];

    /** White at rest, red stretched, blue compressed, full colour at ±{@link #FULL_COLOUR_STRAIN}; into rgb. */
    static void strainColour(double strain, float[] rgb) {
        double s = Math.max(-1, Math.min(1, strain / FULL_COLOUR_STRAIN));
        if (s >= 0) { rgb[0] = 255; rgb[1] = (float) (255 * (1 - s)); rgb[2] = rgb[1]; }
        else { rgb[0] = (float) (255 * (1 + s)); rgb[1] = rgb[0]; rgb[2] = 255; }
    }

    /** Distance constraints as lines: white at rest, red stretched, blue compressed. */
    void drawWireframe(PGraphics g, Scene scene) {
        Particles p = scene.cloth().particles();
        double[] x = p.positions();
        g.strokeWeight(1.5f * strokeUnit);
        g.beginShape(PConstants.LINES);
        for (ConstraintBlock block : scene.simulation().blocks()) {
            if (!(block instanceof DistanceBlock)) continue;
            DistanceBlock d = (DistanceBlock) block;
            for (int i = 0; i < d.count(); i++) {
                strainColour(d.strain(i, p), rgb);
                g.stroke(rgb[0], rgb[1], rgb[2]);
                int a = 3 * d.a(i), b = 3 * d.b(i);
                g.vertex((float) x[a], (float) x[a + 1], (float) x[a + 2]);
                g.vertex((float) x[b], (float) x[b + 1], (float) x[b + 2]);
            }
        }
        g.endShape();
    }

    /** Particles as points, pinned ones larger and orange. */
    void drawParticles(PGraphics g, Particles p, boolean all) {
        double[] x = p.positions();
        if (all) {
            g.stroke(240);
            g.strokeWeight(3 * strokeUnit);
            g.beginShape(PConstants.POINTS);
            for (int i = 0; i < p.count(); i++) if (!p.isPinned(i)) g.vertex((float) x[3 * i], (float) x[3 * i + 1], (float) x[3 * i + 2]);
            g.endShape();
        }
        g.stroke(255, 150, 30);
        g.strokeWeight(9 * strokeUnit);
        g.beginShape(PConstants.POINTS);
        for (int i = 0; i < p.count(); i++) if (p.isPinned(i)) g.vertex((float) x[3 * i], (float) x[3 * i + 1], (float) x[3 * i + 2]);
        g.endShape();
    }

    /** One flag per particle: touching something now (kept while the count stays, so drawing allocates nothing). */
    private boolean[] touching = new boolean[0];

    /**
     * What holds the cloth now: the particles touching a collider or another layer in red, and each listed
     * self-collision pair within the thickness as a yellow line between its two particles.
     */
    void drawContacts(PGraphics g, Simulation sim) {
        Particles p = sim.particles();
        double[] x = p.positions();
        SelfCollision self = sim.selfCollision();
        if (self != null) {
            double reach = 1.01 * self.thickness();
            g.stroke(255, 220, 60);
            g.strokeWeight(1.5f * strokeUnit);
            g.beginShape(PConstants.LINES);
            for (int k = 0, n = self.pairCount(); k < n; k++) {
                int a = 3 * self.pairParticle(k, 0), b = 3 * self.pairParticle(k, 1);
                double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
                if (dx * dx + dy * dy + dz * dz >= reach * reach) continue;
                g.vertex((float) x[a], (float) x[a + 1], (float) x[a + 2]);
                g.vertex((float) x[b], (float) x[b + 1], (float) x[b + 2]);
            }
            g.endShape();
        }
        if (touching.length < p.count()) touching = new boolean[p.count()];
        java.util.Arrays.fill(touching, false);
        sim.markTouching(touching);
        g.stroke(235, 60, 50);
        g.strokeWeight(5 * strokeUnit);
        g.beginShape(PConstants.POINTS);
        for (int i = 0; i < p.count(); i++) if (touching[i] && !p.isPinned(i)) g.vertex((float) x[3 * i], (float) x[3 * i + 1], (float) x[3 * i + 2]);
        g.endShape();
    }

    /** Each box and capsule's triangles, made when first drawn; forgotten with the collider (a reset makes new ones). */
    private final java.util.WeakHashMap<RigidCollider, SolidMesh> solidMeshes = new java.util.WeakHashMap<>();

    /** The collider's mesh, placed where it is now. */
    SolidMesh placed(RigidCollider s) {
        SolidMesh m = solidMeshes.computeIfAbsent(s, SolidMesh::new);
        m.place();
        return m;
    }

    /** A box or a capsule, in the spheres' glazed ceramic. */
    void drawSolid(PGraphics g, RigidCollider s) {
        g.noStroke();
        g.fill(COLLIDER[0], COLLIDER[1], COLLIDER[2]);
        g.specular(230, 226, 215);
        g.shininess(40);
        placed(s).draw(g);
        g.specular(0);
    }

    /** A sphere with two great circles turned by its spin angle, so rotation is visible. */
    void drawSphere(PGraphics g, Sphere s) {
        g.pushMatrix();
        g.translate((float) s.centreX(), (float) s.centreY(), (float) s.centreZ());
        g.noStroke();
        // Glazed ceramic, unlike the matte cloth: a warm white with a tight highlight.
        g.fill(COLLIDER[0], COLLIDER[1], COLLIDER[2]);
        g.specular(230, 226, 215);
        g.shininess(40);
        g.sphereDetail(40);
        g.sphere((float) s.radius() * 0.995f);
        g.specular(0);
        double wl = Math.sqrt(s.omegaX() * s.omegaX() + s.omegaY() * s.omegaY() + s.omegaZ() * s.omegaZ());
        if (wl > 0) g.rotate((float) s.spinAngle(), (float) (s.omegaX() / wl), (float) (s.omegaY() / wl), (float) (s.omegaZ() / wl));
        g.noFill();
        g.strokeWeight(3 * strokeUnit);
        float r = (float) s.radius() * 1.004f;
        g.stroke(220, 60, 60);
        ring(g, r, 0);
        g.stroke(250, 220, 80);
        ring(g, r, 1);
        g.popMatrix();
    }

    /**
     * Whether the caller has drawn the floor (y = 0, with its grid and shadows): a plane collider that is
     * that floor is then not drawn again, since two coplanar surfaces z-fight into stripes. The library,
     * which draws no floor of its own, leaves it false.
     */
    public boolean floorShown;

    /** A plane collider lying in y = 0 facing up: the floor the sketch draws. */
    static boolean isFloor(Plane p) {
        return p.normalY() > 0.999 && Math.abs(p.distance(0, 0, 0)) < 1e-6;
    }

    /**
     * A plane collider as a 1.5 m square of it under the cloth (centred at the foot of the cloth's rest
     * centre), in the colliders' colour, matte: a slope or a floor should not shine. An infinite plane
     * drawn large hides the scene from most camera angles.
     */
    void drawPlane(PGraphics g, Plane p, Cloth near) {
        xpbdcloth.mesh.ClothMesh m = near.mesh();
        double ox = (m.min(0) + m.max(0)) / 2, oy = (m.min(1) + m.max(1)) / 2, oz = (m.min(2) + m.max(2)) / 2;
        double nx = p.normalX(), ny = p.normalY(), nz = p.normalZ(), d = p.distance(ox, oy, oz);
        double cx = ox - d * nx, cy = oy - d * ny, cz = oz - d * nz;
        // Two directions in the plane: u ⟂ n (from whichever axis is least along n), v = n × u.
        double ax = Math.abs(nx) < 0.9 ? 1 : 0, ay = ax == 1 ? 0 : 1;
        double ux = ay * nz, uy = -ax * nz, uz = ax * ny - ay * nx, ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
        ux /= ul; uy /= ul; uz /= ul;
        double vx = ny * uz - nz * uy, vy = nz * ux - nx * uz, vz = nx * uy - ny * ux;
        double h = 0.75;
        g.noStroke();
        g.fill(COLLIDER[0] * 0.55f, COLLIDER[1] * 0.55f, COLLIDER[2] * 0.55f);
        g.beginShape(PConstants.QUADS);
        g.normal((float) nx, (float) ny, (float) nz);
        for (int k = 0; k < 4; k++) {
            double su = (k == 0 || k == 3) ? -h : h, sv = k < 2 ? -h : h;
            g.vertex((float) (cx + su * ux + sv * vx), (float) (cy + su * uy + sv * vy), (float) (cz + su * uz + sv * vz));
        }
        g.endShape();
    }

    /** A circle of radius r in the xz plane (plane 0) or the xy plane (plane 1). */
    private static void ring(PGraphics g, float r, int plane) {
        g.beginShape();
        for (int i = 0; i <= 48; i++) {
            double a = 2 * Math.PI * i / 48;
            float u = (float) (r * Math.cos(a)), v = (float) (r * Math.sin(a));
            if (plane == 0) g.vertex(u, 0, v);
            else g.vertex(u, v, 0);
        }
        g.endShape();
    }

    /** A 4 m square grid on the ground, lines every 25 cm, drawn just above the floor and its shadows. */
    void drawGround(PGraphics g, double centreX) {
        g.strokeWeight(1 * strokeUnit);
        g.stroke(78, 82, 92);
        g.beginShape(PConstants.LINES);
        float half = 2f, y = 2 * GroundShadow.LIFT;
        float cx = (float) (Math.round(centreX * 4) / 4.0);
        for (int i = -8; i <= 8; i++) {
            float u = i * 0.25f;
            g.vertex(cx + u, y, -half); g.vertex(cx + u, y, half);
            g.vertex(cx - half, y, u); g.vertex(cx + half, y, u);
        }
        g.endShape();
    }
}
