package xpbdcloth.engine;

/**
 * A kinematic triangle mesh the cloth cannot pass (a body, a chair, a thin plate): open or closed, still,
 * on a rigid path like the other solids, or animated by frames of its vertices (same triangles; linear
 * between frames, played at {@code fps} from a start time, looped or held at the last). The pose of its
 * vertices is a function of time alone, so a step rolled back needs nothing restored.
 *
 * <p><b>Contact</b> of particle i with triangle t, on the side s = ±1 the particle is on (a closed mesh's
 * outside, taken from its outward normals; for an open mesh the side the particle started the substep on):
 * <pre>
 *   c = the point of t closest to x (Ericson 2005, §5.1.5),   n = s n_t on t's face or behind its plane,
 *   else (x − c)/|x − c| by an edge or a vertex
 *   C(x) = n·(x − c) − m ≥ 0,   ∇C = n,   Δx = −C n   (hard, k = 1, α = 0: the solid is kinematic)
 * </pre>
 * then {@link CoulombFriction} against the surface's velocity at c (the triangle's vertices' motion over
 * the substep, barycentric). The side of a closed mesh is the sign of (x − c) against the angle-weighted
 * pseudonormal of the feature c lies on (Bærentzen and Aanæs 2005, "Signed distance computation using the
 * angle weighted pseudonormal"): correct inside and outside of any closed manifold mesh.
 *
 * <p><b>No tunnelling.</b> The collide stage follows each particle's motion over the substep against each
 * nearby triangle's motion (both linear in the substep) with the cubic coplanarity test
 * ({@link TriangleGeometry#firstCoplanarTime}): a particle that crosses a triangle between two checks gets
 * a contact with that triangle on the side it came from, however thin the mesh and however fast either
 * moves. Each particle gets at most three contacts per mesh and substep: the first triangle it crossed;
 * the one nearest to where it started the substep among those within reach of its motion (margin +
 * {@link #REACH} around it), nearest at the start and not at the predicted end, which may already lie past
 * a thin solid, nearer its far side; and, when it crossed nothing and another part of the body faces it
 * from elsewhere (a crease: an arm against the side), the one nearest to its predicted end, so the sweeps
 * hold it off both.
 *
 * <p>Candidates come from a {@link TriangleBvh} refitted each substep to the triangles' swept boxes.
 * Contacts are found and projected on one thread; nothing is allocated per step.
 */
public final class MeshCollider extends RigidCollider {
    /** How far beyond the margin (m) a triangle is still a candidate: what the sweeps may push a particle in a substep. */
    public static final double REACH = 0.01;
    /** Barycentric slack of the crossing test, so a crossing exactly through an edge is not missed between two triangles. */
    static final double EDGE_SLACK = 1e-9;

    private final int[] triangles;
    private final int triangleCount, vertexCount;
    private final double[] localRest;
    private final double[][] frames;
    private final double fps;
    private final boolean loop;
    /** The time (s) the frames start to play; before it the mesh holds its first frame. */
    private final double playFrom;
    private final boolean closed;
    private final double boundingRadius;
    /** World vertices at the substep's start and now; the local pose now. */
    private double[] start, now;
    private final double[] local;
    /** Unit face normals, angle-weighted vertex and summed edge pseudonormals, at the substep's start and now. */
    private double[] faceStart, faceNow, vertexStart, vertexNow, edgeStart, edgeNow;
    /** Edge index of each triangle's sides ab, bc, ca. */
    private final int[] edgeOf;
    private final int edgeCount;
    private final TriangleBvh bvh;
    /** This substep's contacts: particle, triangle, side and how deep inside (minus margin) it started. */
    private int[] contactParticle = new int[0], contactTriangle = new int[0];
    private double[] contactSide = new double[0], contactStartDepth = new double[0];
    private int contacts;
    /** Candidate triangles of one particle; grows (rarely, outside any steady state) when a query fills it. */
    private int[] candidates = new int[512];
    /** Scratch of the collide stage and of measurements (one thread). */
    private final double[] point = new double[6], scratch = new double[9];
    /** The triangle the last {@link #distance} query found nearest, and the feature of it the closest point lies on. */
    private int nearestTriangle, nearestFeature;
    /**
     * Scratch of the projection, one per thread: vertex block descent projects the contacts of the particles
     * of one colour on several threads at once (no allocation after a thread's first contact).
     */
    private final ThreadLocal<double[][]> projectionScratch = ThreadLocal.withInitial(() -> new double[][] {new double[6], new double[9]});
    private double queryX, queryY, queryZ;
    private final TriangleBvh.TriangleMetric toQuery = this::squaredDistanceToQuery;

    /**
     * @param path      the path of the point that is the origin of the mesh's own frame (its position at
     *                  t = 0 is where the mesh's coordinates are measured from)
     * @param vertices  the mesh's vertices at t = 0, world coordinates, 3 per vertex
     * @param triangles 3 vertex indices per triangle
     * @param frames    null for a rigid mesh; else its vertices per frame (world coordinates at the path's
     *                  start), each as many as {@code vertices}
     * @param fps       frames per second of the animation (ignored without frames)
     * @param loop      whether the animation starts again after its last frame (else it holds it)
     */
    public MeshCollider(SpherePath path, double[] vertices, int[] triangles, double[][] frames, double fps, boolean loop,
                        double margin, double staticFriction, double kineticFriction) {
        this(path, vertices, triangles, frames, fps, loop, 0, margin, staticFriction, kineticFriction);
    }

    /**
     * The same, with the frames played from time {@code playFrom} (s, ≥ 0) on: before it the mesh holds its first
     * frame (a body that stands still while a garment is sewn onto it, then moves).
     */
    public MeshCollider(SpherePath path, double[] vertices, int[] triangles, double[][] frames, double fps, boolean loop, double playFrom,
                        double margin, double staticFriction, double kineticFriction) {
        super(path, Rotation.identity(), margin, staticFriction, kineticFriction);
        Check.nonNegative("playFrom", playFrom);
        if (vertices == null || vertices.length == 0 || vertices.length % 3 != 0)
            throw new IllegalArgumentException("vertices must be 3 numbers per vertex, at least one vertex, was " + (vertices == null ? "null" : vertices.length + " numbers"));
        if (triangles == null || triangles.length == 0 || triangles.length % 3 != 0)
            throw new IllegalArgumentException("triangles must be 3 indices per triangle, at least one, was " + (triangles == null ? "null" : triangles.length + " indices"));
        vertexCount = vertices.length / 3;
        triangleCount = triangles.length / 3;
        for (int k = 0; k < triangles.length; k++)
            if (triangles[k] < 0 || triangles[k] >= vertexCount)
                throw new IllegalArgumentException("triangle " + k / 3 + " corner must be a vertex index in [0, " + (vertexCount - 1) + "], was " + triangles[k]);
        double[] origin = new double[3];
        path.centreAt(0, origin);
        localRest = toLocal(vertices, origin, "vertices");
        if (frames != null) {
            if (frames.length == 0) throw new IllegalArgumentException("frames must hold at least one frame, was none");
            if (!(fps > 0 && fps <= 1000)) throw new IllegalArgumentException("fps must be in (0, 1000], was " + fps);
            this.frames = new double[frames.length][];
            for (int f = 0; f < frames.length; f++) {
                if (frames[f] == null || frames[f].length != vertices.length)
                    throw new IllegalArgumentException("frame " + f + " must have " + vertexCount + " vertices like the mesh, was " + (frames[f] == null ? "null" : frames[f].length / 3));
                this.frames[f] = toLocal(frames[f], origin, "frame " + f);
            }
        } else {
            this.frames = null;
        }
        this.fps = fps;
        this.loop = loop;
        this.playFrom = playFrom;
        // Whether every edge has exactly two triangles (closed: it has an inside); a closed mesh wound inwards
        // is turned so that every normal points out.
        this.triangles = triangles.clone();
        TriangleEdges numbered = TriangleEdges.of(this.triangles, vertexCount);
        boolean everyEdgeTwice = true;
        for (int e = 0; e < numbered.count(); e++) everyEdgeTwice &= numbered.uses(e) == 2;
        closed = everyEdgeTwice;
        edgeCount = numbered.count();
        if (closed && signedVolume(this.triangles, localRest) < 0) {
            for (int t = 0; t < triangleCount; t++) { int s = this.triangles[3 * t + 1]; this.triangles[3 * t + 1] = this.triangles[3 * t + 2]; this.triangles[3 * t + 2] = s; }
            numbered = TriangleEdges.of(this.triangles, vertexCount);
        }
        edgeOf = numbered.edgeOfSides();
        double radius = 0;
        for (double[] f : this.frames == null ? new double[][] {localRest} : this.frames)
            for (int v = 0; v < vertexCount; v++) radius = Math.max(radius, Math.sqrt(f[3 * v] * f[3 * v] + f[3 * v + 1] * f[3 * v + 1] + f[3 * v + 2] * f[3 * v + 2]));
        boundingRadius = radius;
        local = localRest.clone();
        start = new double[vertices.length];
        now = new double[vertices.length];
        faceStart = new double[3 * triangleCount];
        faceNow = new double[3 * triangleCount];
        vertexStart = new double[vertices.length];
        vertexNow = new double[vertices.length];
        edgeStart = new double[3 * edgeCount];
        edgeNow = new double[3 * edgeCount];
        bvh = new TriangleBvh(this.triangles, localRest);
        moveTo(0);
    }

    private static double[] toLocal(double[] world, double[] origin, String what) {
        double[] out = new double[world.length];
        for (int i = 0; i < world.length; i++) {
            if (!Double.isFinite(world[i]) || Math.abs(world[i]) > EngineRange.MAX_POSITION)
                throw new IllegalArgumentException(what + " coordinate " + i + " must be finite and within ±" + EngineRange.MAX_POSITION + " m, was " + world[i]);
            out[i] = world[i] - origin[i % 3];
        }
        return out;
    }

    private static double signedVolume(int[] triangles, double[] v) {
        double vol = 0;
        int triangleCount = triangles.length / 3;
        for (int t = 0; t < triangleCount; t++) {
            int a = 3 * triangles[3 * t], b = 3 * triangles[3 * t + 1], c = 3 * triangles[3 * t + 2];
            vol += v[a] * (v[b + 1] * v[c + 2] - v[b + 2] * v[c + 1]) - v[a + 1] * (v[b] * v[c + 2] - v[b + 2] * v[c]) + v[a + 2] * (v[b] * v[c + 1] - v[b + 1] * v[c]);
        }
        return vol / 6;
    }

    // ---- Pose -------------------------------------------------------------------------------------------

    @Override public void moveTo(double t) {
        super.moveTo(t);
        if (local == null) return; // RigidCollider's constructor places the frame before this one has its mesh
        pose(t, now);
        System.arraycopy(now, 0, start, 0, now.length);
        normals(now, faceNow, vertexNow, edgeNow);
        System.arraycopy(faceNow, 0, faceStart, 0, faceNow.length);
        System.arraycopy(vertexNow, 0, vertexStart, 0, vertexNow.length);
        System.arraycopy(edgeNow, 0, edgeStart, 0, edgeNow.length);
        bvh.refit(start, now, margin + REACH);
    }

    @Override void advance(double t, double h) {
        super.advance(t, h);
        // A still mesh (no frames, no spin, its centre where it was) keeps its vertices, normals and boxes.
        if (frames == null && omegaX == 0 && omegaY == 0 && omegaZ == 0 && cx == pcx && cy == pcy && cz == pcz) return;
        double[] s = start; start = now; now = s;
        s = faceStart; faceStart = faceNow; faceNow = s;
        s = vertexStart; vertexStart = vertexNow; vertexNow = s;
        s = edgeStart; edgeStart = edgeNow; edgeNow = s;
        pose(t, now);
        normals(now, faceNow, vertexNow, edgeNow);
        bvh.refit(start, now, margin + REACH);
    }

    /** World vertices at time t: the frame (interpolated) in the solid's frame, turned by R(t) and carried to c(t). */
    private void pose(double t, double[] out) {
        double[] v = localRest;
        if (frames != null) {
            int n = frames.length;
            double f = Math.max(0, t - playFrom) * fps;
            if (loop) f = ((f % n) + n) % n;
            else f = Math.max(0, Math.min(n - 1, f));
            int i = (int) Math.floor(f);
            double w = f - i;
            int j = loop ? (i + 1) % n : Math.min(i + 1, n - 1);
            double[] a = frames[Math.min(i, n - 1)], b = frames[j];
            for (int k = 0; k < local.length; k++) local[k] = a[k] + w * (b[k] - a[k]);
            v = local;
        }
        double[] r = rotation;
        for (int k = 0; k < v.length; k += 3) {
            double x = v[k], y = v[k + 1], z = v[k + 2];
            out[k] = cx + r[0] * x + r[1] * y + r[2] * z;
            out[k + 1] = cy + r[3] * x + r[4] * y + r[5] * z;
            out[k + 2] = cz + r[6] * x + r[7] * y + r[8] * z;
        }
    }

    /** Unit face normals, angle-weighted vertex pseudonormals and edge pseudonormals (the sum of the two faces') of vertices v. */
    private void normals(double[] v, double[] face, double[] vertex, double[] edge) {
        java.util.Arrays.fill(vertex, 0);
        java.util.Arrays.fill(edge, 0);
        for (int t = 0; t < triangleCount; t++) {
            int a = 3 * triangles[3 * t], b = 3 * triangles[3 * t + 1], c = 3 * triangles[3 * t + 2];
            double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
            double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (len > 0) { nx /= len; ny /= len; nz /= len; }
            face[3 * t] = nx; face[3 * t + 1] = ny; face[3 * t + 2] = nz;
            for (int e = 0; e < 3; e++) {
                int g = 3 * edgeOf[3 * t + e];
                edge[g] += nx; edge[g + 1] += ny; edge[g + 2] += nz;
                int p = 3 * triangles[3 * t + e], q = 3 * triangles[3 * t + (e + 1) % 3], o = 3 * triangles[3 * t + (e + 2) % 3];
                double angle = angle(v, p, q, o);
                vertex[p] += angle * nx; vertex[p + 1] += angle * ny; vertex[p + 2] += angle * nz;
            }
        }
    }

    /** The triangle's angle at corner p (between p→q and p→o). */
    private static double angle(double[] v, int p, int q, int o) {
        double ux = v[q] - v[p], uy = v[q + 1] - v[p + 1], uz = v[q + 2] - v[p + 2];
        double wx = v[o] - v[p], wy = v[o + 1] - v[p + 1], wz = v[o + 2] - v[p + 2];
        double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), ux * wx + uy * wy + uz * wz);
    }

    /** The pseudonormal (not unit) of the feature of triangle t a closest point lies on. */
    private static int pseudonormal(int feature, int t, int[] triangles, int[] edgeOf, double[] face, double[] vertex, double[] edge, double[] out) {
        double[] src;
        int at;
        switch (feature) {
            case TriangleGeometry.FACE: src = face; at = 3 * t; break;
            case TriangleGeometry.EDGE_AB: src = edge; at = 3 * edgeOf[3 * t]; break;
            case TriangleGeometry.EDGE_BC: src = edge; at = 3 * edgeOf[3 * t + 1]; break;
            case TriangleGeometry.EDGE_CA: src = edge; at = 3 * edgeOf[3 * t + 2]; break;
            case TriangleGeometry.VERTEX_A: src = vertex; at = 3 * triangles[3 * t]; break;
            case TriangleGeometry.VERTEX_B: src = vertex; at = 3 * triangles[3 * t + 1]; break;
            default: src = vertex; at = 3 * triangles[3 * t + 2]; break;
        }
        out[6] = src[at]; out[7] = src[at + 1]; out[8] = src[at + 2];
        return at;
    }

    // ---- Contacts ---------------------------------------------------------------------------------------

    @Override void findContacts(Particles p, double h, ContactSet set) {
        final double[] x = p.x, prev = p.prev, w = p.w;
        contacts = 0;
        double reach = margin + REACH;
        double rx0 = bvh.rootMin(0), ry0 = bvh.rootMin(1), rz0 = bvh.rootMin(2), rx1 = bvh.rootMax(0), ry1 = bvh.rootMax(1), rz1 = bvh.rootMax(2);
        for (int i = 0, n = p.count(); i < n; i++) {
            if (w[i] == 0) continue;
            int k = 3 * i;
            double ax = prev[k], ay = prev[k + 1], az = prev[k + 2], bx = x[k], by = x[k + 1], bz = x[k + 2];
            double lx = Math.min(ax, bx) - reach, ly = Math.min(ay, by) - reach, lz = Math.min(az, bz) - reach;
            double hx = Math.max(ax, bx) + reach, hy = Math.max(ay, by) + reach, hz = Math.max(az, bz) + reach;
            if (lx > rx1 || hx < rx0 || ly > ry1 || hy < ry0 || lz > rz1 || hz < rz0) continue;
            int found = bvh.overlapping(lx, ly, lz, hx, hy, hz, candidates);
            while (found == candidates.length) { // a dense mesh or a long motion: look again with room for all
                candidates = new int[2 * candidates.length];
                found = bvh.overlapping(lx, ly, lz, hx, hy, hz, candidates);
            }
            double firstHit = 2, nearest = Double.MAX_VALUE, nearestAhead = (margin + REACH) * (margin + REACH);
            int hit = -1, near = -1, ahead = -1;
            for (int c = 0; c < found; c++) {
                int t = candidates[c], a = triangles[3 * t], b = triangles[3 * t + 1], d = triangles[3 * t + 2];
                if (mayCross(t, ax, ay, az, bx, by, bz)) {
                    double tau = TriangleGeometry.firstCoplanarTime(ax, ay, az, bx, by, bz, start, now, a, b, d, EDGE_SLACK, scratch);
                    if (tau >= 0 && tau < firstHit) { firstHit = tau; hit = t; }
                }
                TriangleGeometry.closestPoint(ax, ay, az, start, a, b, d, point);
                double ex = ax - point[0], ey = ay - point[1], ez = az - point[2], d2 = ex * ex + ey * ey + ez * ez;
                if (d2 < nearest) { nearest = d2; near = t; }
                TriangleGeometry.closestPoint(bx, by, bz, now, a, b, d, point);
                ex = bx - point[0]; ey = by - point[1]; ez = bz - point[2]; d2 = ex * ex + ey * ey + ez * ez;
                if (d2 < nearestAhead) { nearestAhead = d2; ahead = t; }
            }
            if (hit >= 0) add(set, i, hit, ax, ay, az, true);
            if (near >= 0 && near != hit) add(set, i, near, ax, ay, az, false);
            if (hit < 0 && ahead >= 0 && ahead != near && !sameSurface(ahead, near) && faces(ahead, ax, ay, az)) add(set, i, ahead, ax, ay, az, false);
        }
    }

    /**
     * Whether the particle's motion a → b may cross triangle t's plane in the substep: always when the
     * triangle moved; for a still one only when a and b lie on different sides of its plane (the motion is
     * then linear in the plane's distance, so the cubic has no root otherwise).
     */
    private boolean mayCross(int t, double ax, double ay, double az, double bx, double by, double bz) {
        int a = 3 * triangles[3 * t], b = 3 * triangles[3 * t + 1], c = 3 * triangles[3 * t + 2];
        if (start[a] != now[a] || start[a + 1] != now[a + 1] || start[a + 2] != now[a + 2] || start[b] != now[b] || start[b + 1] != now[b + 1]
                || start[b + 2] != now[b + 2] || start[c] != now[c] || start[c + 1] != now[c + 1] || start[c + 2] != now[c + 2]) return true;
        double nx = faceNow[3 * t], ny = faceNow[3 * t + 1], nz = faceNow[3 * t + 2];
        double da = (ax - now[a]) * nx + (ay - now[a + 1]) * ny + (az - now[a + 2]) * nz;
        double db = (bx - now[a]) * nx + (by - now[a + 1]) * ny + (bz - now[a + 2]) * nz;
        return (da <= 0) != (db <= 0) || da == 0 || db == 0;
    }

    /** Whether the point lies on the side triangle t's face points to (at the substep's start): the triangle faces it. */
    private boolean faces(int t, double ax, double ay, double az) {
        int a = 3 * triangles[3 * t];
        return (ax - start[a]) * faceStart[3 * t] + (ay - start[a + 1]) * faceStart[3 * t + 1] + (az - start[a + 2]) * faceStart[3 * t + 2] > 0;
    }

    /** Whether triangles s and t face the same way (within about 25°): one surface, one contact is enough. */
    private boolean sameSurface(int s, int t) {
        if (t < 0) return false;
        return faceNow[3 * s] * faceNow[3 * t] + faceNow[3 * s + 1] * faceNow[3 * t + 1] + faceNow[3 * s + 2] * faceNow[3 * t + 2] > 0.9;
    }

    /**
     * A contact of particle i with triangle t, on the side it started the substep on (a closed mesh's
     * outside always); crossed: it went through t's plane inside t during the substep.
     */
    private void add(ContactSet set, int i, int t, double ax, double ay, double az, boolean crossed) {
        int feature = TriangleGeometry.closestPoint(ax, ay, az, start, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2], point);
        double dx = ax - point[0], dy = ay - point[1], dz = az - point[2], distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double side, signed;
        if (crossed && !closed) {
            // The side of t's plane it came from.
            double along = dx * faceStart[3 * t] + dy * faceStart[3 * t + 1] + dz * faceStart[3 * t + 2];
            side = along >= 0 ? 1 : -1;
            signed = distance;
        } else {
            pseudonormal(feature, t, triangles, edgeOf, faceStart, vertexStart, edgeStart, scratch);
            double along = dx * scratch[6] + dy * scratch[7] + dz * scratch[8];
            if (closed) { side = 1; signed = along >= 0 ? distance : -distance; }
            else { side = along >= 0 ? 1 : -1; signed = distance; }
        }
        if (contacts == contactParticle.length) {
            int size = Math.max(64, 2 * contacts);
            contactParticle = java.util.Arrays.copyOf(contactParticle, size);
            contactTriangle = java.util.Arrays.copyOf(contactTriangle, size);
            contactSide = java.util.Arrays.copyOf(contactSide, size);
            contactStartDepth = java.util.Arrays.copyOf(contactStartDepth, size);
        }
        contactParticle[contacts] = i;
        contactTriangle[contacts] = t;
        contactSide[contacts] = side;
        contactStartDepth[contacts] = margin - signed;
        set.add(i, contacts, this);
        contacts++;
    }

    /**
     * C of contact j now, its normal into scratch[6..8], the closest point and its weights into point. On a
     * closed mesh the particle is outside when (x − c) points the way of the pseudonormal of the feature c
     * lies on; then n = (x − c)/|x − c| and C = |x − c| − m, else n = −(x − c)/|x − c| and C = −|x − c| − m:
     * out through the nearest point, not along a face normal that, beside an edge, points elsewhere.
     */
    private double constraint(Particles p, int j, double[] point, double[] scratch) {
        int i = contactParticle[j], t = contactTriangle[j], k = 3 * i;
        double s = contactSide[j];
        double px = p.x[k], py = p.x[k + 1], pz = p.x[k + 2];
        int feature = TriangleGeometry.closestPoint(px, py, pz, now, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2], point);
        double dx = px - point[0], dy = py - point[1], dz = pz - point[2], len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (!closed) {
            // An open sheet has no inside: on its face, or behind its plane, the particle is held to side s
            // along the face normal; off an edge in front of it, away from the edge.
            double fx = s * faceNow[3 * t], fy = s * faceNow[3 * t + 1], fz = s * faceNow[3 * t + 2];
            double along = dx * fx + dy * fy + dz * fz;
            if (feature == TriangleGeometry.FACE || !(along > 0) || len < 1e-12) {
                scratch[6] = fx; scratch[7] = fy; scratch[8] = fz;
                return along - margin;
            }
            scratch[6] = dx / len; scratch[7] = dy / len; scratch[8] = dz / len;
            return len - margin;
        }
        pseudonormal(feature, t, triangles, edgeOf, faceNow, vertexNow, edgeNow, scratch);
        double sx = s * scratch[6], sy = s * scratch[7], sz = s * scratch[8];
        if (len < 1e-12) { // on the surface: out along the pseudonormal
            double l = Math.sqrt(sx * sx + sy * sy + sz * sz);
            scratch[6] = sx / l; scratch[7] = sy / l; scratch[8] = sz / l;
            return -margin;
        }
        double sign = dx * sx + dy * sy + dz * sz >= 0 ? 1 : -1;
        scratch[6] = sign * dx / len; scratch[7] = sign * dy / len; scratch[8] = sign * dz / len;
        return sign * len - margin;
    }

    @Override void project(Particles p, int j, double h) {
        int i = contactParticle[j];
        if (p.w[i] == 0) return;
        double[][] work = projectionScratch.get();
        double[] point = work[0], scratch = work[1];
        double c = constraint(p, j, point, scratch);
        if (c >= 0) return;
        double correction = -c - leftInside(p, i, contactStartDepth[j], h);
        if (correction <= 0) return;
        double nx = scratch[6], ny = scratch[7], nz = scratch[8];
        int k = 3 * i;
        p.x[k] += correction * nx; p.x[k + 1] += correction * ny; p.x[k + 2] += correction * nz;
        // The start moved out with it: the next projection of this contact undoes no more than is left.
        contactStartDepth[j] -= depenetrateWithoutVelocity(p, k, nx, ny, nz, correction, contactStartDepth[j], h);
        // The surface's velocity at the closest point: its triangle's vertices' motion over the substep.
        int t = contactTriangle[j];
        double vx = 0, vy = 0, vz = 0;
        for (int corner = 0; corner < 3; corner++) {
            int v = 3 * triangles[3 * t + corner];
            double wgt = point[3 + corner] / h;
            vx += wgt * (now[v] - start[v]); vy += wgt * (now[v + 1] - start[v + 1]); vz += wgt * (now[v + 2] - start[v + 2]);
        }
        CoulombFriction.apply(p, i, nx, ny, nz, correction, vx, vy, vz, h, staticFriction, kineticFriction);
    }

    @Override double clearance(Particles p, int j) {
        double[][] work = projectionScratch.get();
        return constraint(p, j, work[0], work[1]);
    }

    // ---- The shape, for the rest of the engine and for measurements ------------------------------------

    /**
     * The distance from world point (x, y, z) to the mesh now, m: negative inside a closed mesh, never
     * negative for an open one. Inside is where the mesh's winding number is at least ½ (Jacobson et al.
     * 2013, "Robust inside-outside segmentation using generalized winding numbers"): right also inside a
     * body made of closed parts that overlap, where the nearest surface may be another part's, seen from
     * outside it. A measurement (it visits every triangle), not the contact's own test.
     */
    public double signedDistance(double x, double y, double z) {
        double d = distance(x, y, z);
        return closed && windingNumber(x, y, z) >= 0.5 ? -d : d;
    }

    /**
     * C at a world point (see {@link Collider#clearanceAt}), decided as the contacts decide it: outside a closed
     * mesh where the point lies the way of the pseudonormal of the nearest feature (one nearest-triangle query,
     * not {@link #signedDistance}'s winding number over every triangle); an open mesh has no inside. Inside two
     * overlapping closed parts near the other's surface it can read outside, where the winding number would not.
     */
    @Override public double clearanceAt(double x, double y, double z) {
        double d = distance(x, y, z); // leaves the nearest triangle's closest point in point
        if (!closed || d < 1e-12) return d - margin;
        pseudonormal(nearestFeature, nearestTriangle, triangles, edgeOf, faceNow, vertexNow, edgeNow, scratch);
        double along = (x - point[0]) * scratch[6] + (y - point[1]) * scratch[7] + (z - point[2]) * scratch[8];
        return (along >= 0 ? d : -d) - margin;
    }

    /** The unsigned distance from world point (x, y, z) to the mesh now, m. */
    public double distance(double x, double y, double z) {
        queryX = x; queryY = y; queryZ = z;
        int t = bvh.nearest(x, y, z, Double.POSITIVE_INFINITY, toQuery);
        nearestTriangle = t;
        nearestFeature = TriangleGeometry.closestPoint(x, y, z, now, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2], point);
        double dx = x - point[0], dy = y - point[1], dz = z - point[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * The winding number of the mesh now about world point p: the triangles' signed solid angles over 4π
     * (each by Van Oosterom and Strackee 1983, "The solid angle of a plane triangle"). 1 inside a closed
     * part, 0 outside every part, the number of parts that hold p where closed parts overlap.
     */
    public double windingNumber(double px, double py, double pz) {
        double sum = 0;
        for (int t = 0; t < triangleCount; t++) {
            int a = 3 * triangles[3 * t], b = 3 * triangles[3 * t + 1], c = 3 * triangles[3 * t + 2];
            double ax = now[a] - px, ay = now[a + 1] - py, az = now[a + 2] - pz;
            double bx = now[b] - px, by = now[b + 1] - py, bz = now[b + 2] - pz;
            double cx = now[c] - px, cy = now[c + 1] - py, cz = now[c + 2] - pz;
            double la = Math.sqrt(ax * ax + ay * ay + az * az), lb = Math.sqrt(bx * bx + by * by + bz * bz), lc = Math.sqrt(cx * cx + cy * cy + cz * cz);
            double det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
            double div = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (bx * cx + by * cy + bz * cz) * la + (cx * ax + cy * ay + cz * az) * lb;
            sum += 2 * Math.atan2(det, div);
        }
        return sum / (4 * Math.PI);
    }

    private double squaredDistanceToQuery(int t) {
        TriangleGeometry.closestPoint(queryX, queryY, queryZ, now, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2], point);
        double dx = queryX - point[0], dy = queryY - point[1], dz = queryZ - point[2];
        return dx * dx + dy * dy + dz * dz;
    }

    /** Signed distance in the solid's own frame (what {@link RigidCollider} asks of a shape), with the unit direction away from the surface into n. */
    @Override double distance(double qx, double qy, double qz, double[] n) {
        double x = cx + worldX3(qx, qy, qz, 0), y = cy + worldX3(qx, qy, qz, 3), z = cz + worldX3(qx, qy, qz, 6);
        double d = signedDistance(x, y, z);
        double gx = x - point[0], gy = y - point[1], gz = z - point[2], len = Math.sqrt(gx * gx + gy * gy + gz * gz);
        if (len > 0) { double s = d < 0 ? -1 / len : 1 / len; gx *= s; gy *= s; gz *= s; }
        n[0] = rotation[0] * gx + rotation[3] * gy + rotation[6] * gz;
        n[1] = rotation[1] * gx + rotation[4] * gy + rotation[7] * gz;
        n[2] = rotation[2] * gx + rotation[5] * gy + rotation[8] * gz;
        return d;
    }

    private double worldX3(double x, double y, double z, int row) { return rotation[row] * x + rotation[row + 1] * y + rotation[row + 2] * z; }

    @Override double boundingRadius() { return boundingRadius; }

    /** A mesh has no thickness of its own; a plate is as thin as zero. */
    @Override double halfThickness() { return 0; }

    /** Whether every edge has exactly two triangles: the mesh has an inside. */
    public boolean closed() { return closed; }
    public int triangleCount() { return triangleCount; }
    public int vertexCount() { return vertexCount; }
    /** Vertex indices, 3 per triangle, each turned to face out of a closed mesh. */
    public int[] triangles() { return triangles.clone(); }
    /** The world positions of the vertices now, 3 per vertex (a view: read it, do not keep it). */
    public double[] vertices() { return now; }
    /** Whether it is animated by frames. */
    public boolean animated() { return frames != null; }
}
