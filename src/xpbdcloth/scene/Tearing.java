package xpbdcloth.scene;

import java.util.Arrays;
import xpbdcloth.engine.BreakingEdges;
import xpbdcloth.engine.Cloth;
import xpbdcloth.engine.Particles;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.VertexSplit;

/**
 * A cloth cut where it tore. At the edge the last step broke ({@link BreakingEdges}), one end is split by
 * the plane through it square to the edge ({@link VertexSplit}: the first end if that parts its triangles,
 * else the other); the copy takes the rest position, position and velocity of the vertex it came from. The cloth is then built again from the cut rest mesh, as the preset builds any mesh
 * cloth, so its constraints, masses (lumped from the same areas: the total is unchanged), contacts and drawing
 * follow the new topology, and it carries on from the torn scene's state ({@code Simulation.continueFrom}).
 * The particles keep their indices (pins, pin motions and vertex groups still name them); the copy comes last.
 * Allocates only here, at a tear.
 */
final class Tearing {
    private Tearing() {}

    static Scene torn(Scene before) {
        BreakingEdges broken = before.breaking();
        Cloth cloth = before.cloth();
        Particles p = cloth.particles();
        int n = p.count(), a = broken.brokenA(), b = broken.brokenB();
        int[] triangles = cloth.triangles();
        double[] x = p.positions();
        double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1], dz = x[3 * b + 2] - x[3 * a + 2];
        // Checked before anything is made: a cloth whose broken edge cannot be cut goes on as it is, allocating nothing.
        int vertex = VertexSplit.cuts(triangles, x, a, dx, dy, dz) ? a : VertexSplit.cuts(triangles, x, b, -dx, -dy, -dz) ? b : -1;
        if (vertex < 0) return before;
        double sign = vertex == a ? 1 : -1;
        triangles = triangles.clone();
        VertexSplit.split(triangles, x, vertex, sign * dx, sign * dy, sign * dz, n);
        double[] rest = Arrays.copyOf(cloth.mesh().positions(), 3 * (n + 1));
        System.arraycopy(rest, 3 * vertex, rest, 3 * n, 3);
        int[] source = new int[n + 1];
        for (int i = 0; i < n; i++) source[i] = i;
        source[n] = vertex;
        ClothMesh was = cloth.mesh();
        int[][] faces = new int[triangles.length / 3][];
        for (int t = 0; t < faces.length; t++) faces[t] = Arrays.copyOfRange(triangles, 3 * t, 3 * t + 3);
        double[] uvs = was.triangleUVs();
        ClothMesh mesh;
        if (uvs == null) mesh = ClothMesh.of(rest, faces, triangles, null, was.groups());
        else {
            double[][] faceUVs = new double[faces.length][];
            for (int t = 0; t < faces.length; t++) faceUVs[t] = Arrays.copyOfRange(uvs, 6 * t, 6 * t + 6);
            mesh = ClothMesh.withTextureCoordinates(rest, faces, faceUVs, null, was.groups());
        }
        int pinned = 0;
        for (int i = 0; i < n; i++) if (p.isPinned(i)) pinned++;
        int[] pins = new int[pinned];
        for (int i = 0, j = 0; i < n; i++) if (p.isPinned(i)) pins[j++] = i;

        Preset at = before.preset();
        Preset.Cloth c = at.cloth;
        Preset.Cloth cut = new Preset.Cloth(mesh, c.meshFile != null ? c.meshFile : at.name + " (torn)", c.arealDensity, c.totalMass, pins);
        Preset preset = new Preset(at.source, at.name, at.description, cut, at.families, before.simulation().settings(), at.spheres, at.planes, at.solids,
                at.bodies, at.selfCollision, at.pinMotions, at.wind, at.fabric, at.aerodynamics, at.pressure);
        Scene after = Scene.of(preset);
        if (before.fabric() != null && before.fabric() != at.fabric.fabric) after.useFabric(before.fabric());
        after.setWind(before.windOn());
        after.wind().setVelocity(before.wind().velocityX(), before.wind().velocityY(), before.wind().velocityZ());
        after.breaking().setBreakingStrain(broken.breakingStrain());
        after.simulation().continueFrom(before.simulation(), source);
        after.followState();
        before.simulation().close();
        return after;
    }
}
