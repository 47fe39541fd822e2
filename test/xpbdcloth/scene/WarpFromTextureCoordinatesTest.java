package xpbdcloth.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.function.BiFunction;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import xpbdcloth.mesh.ClothMesh;
import xpbdcloth.mesh.MeshFileException;
import xpbdcloth.mesh.ObjReader;

/**
 * A fabric's warp from the mesh's texture coordinates: the direction in which u grows, whatever the
 * triangles' edges. A mesh whose u runs along a direction is the same cloth as that mesh given the
 * direction; without texture coordinates or a direction, the preset says which it needs.
 */
class WarpFromTextureCoordinatesTest {
    @TempDir Path dir;

    /** An n × n square of quads in the xy-plane, 0.4 m wide, texture coordinates (u, v) = uv(x, y). */
    static String square(int n, BiFunction<Double, Double, double[]> uv) {
        StringBuilder s = new StringBuilder();
        for (int r = 0; r <= n; r++)
            for (int c = 0; c <= n; c++) {
                double x = 0.4 * c / n, y = -0.4 * r / n;
                s.append(String.format(Locale.ROOT, "v %.17g %.17g 0%n", x, y));
                double[] t = uv.apply(x, y);
                s.append(String.format(Locale.ROOT, "vt %.17g %.17g%n", t[0], t[1]));
            }
        for (int r = 0; r < n; r++)
            for (int c = 0; c < n; c++) {
                int a = r * (n + 1) + c + 1, b = a + 1, d = a + n + 1, e = d + 1;
                s.append("f ").append(a).append('/').append(a).append(' ').append(d).append('/').append(d).append(' ')
                        .append(e).append('/').append(e).append(' ').append(b).append('/').append(b).append('\n');
            }
        return s.toString();
    }

    String scene(String obj, String warp) throws IOException {
        Files.writeString(dir.resolve("square.obj"), obj);
        String text = "{ \"name\": \"w\", \"cloth\": { \"mesh\": { \"file\": \"square.obj\" }, \"pins\": [0, 8] },"
                + " \"fabric\": { \"catalogue\": \"denim\"" + (warp == null ? "" : ", \"warp\": " + warp) + ", \"tethers\": false },"
                + " \"solver\": { \"mode\": \"XPBD\", \"iterations\": 4, \"substeps\": 4, \"dt\": 0.02 } }";
        Path p = dir.resolve("w.json");
        Files.writeString(p, text);
        return p.toString();
    }

    double[] run(String presetFile) {
        Scene s = Scene.of(PresetLoader.load(Path.of(presetFile)));
        for (int k = 0; k < 30; k++) s.simulation().step();
        return s.cloth().particles().positions().clone();
    }

    /**
     * Denim is five times stiffer along v than along u, so the warp matters. u along x, u along a
     * direction 30° from x (sheared and scaled in texture space, which changes no direction), and u along
     * −y: each hangs exactly as the same mesh told the direction in words.
     */
    @Test
    void theWarpIsWhereUGrows() throws IOException {
        double c = Math.cos(Math.toRadians(30)), s = Math.sin(Math.toRadians(30));
        Object[][] cases = {
                {(BiFunction<Double, Double, double[]>) (x, y) -> new double[] {x, y}, "[1, 0, 0]"},
                // ∂x/∂u moves along a line of constant v: v depends only on −x s + y c, so that line is (c, s),
                // however u is scaled and sheared.
                {(BiFunction<Double, Double, double[]>) (x, y) -> new double[] {2 * (x * c + y * s) + 0.7 * (-x * s + y * c), 3 * (-x * s + y * c)},
                        String.format(Locale.ROOT, "[%.17g, %.17g, 0]", c, s)},
                {(BiFunction<Double, Double, double[]>) (x, y) -> new double[] {-y, x}, "[0, -1, 0]"},
        };
        double[] previous = null;
        for (Object[] k : cases) {
            @SuppressWarnings("unchecked") BiFunction<Double, Double, double[]> uv = (BiFunction<Double, Double, double[]>) k[0];
            String obj = square(8, uv);
            double[] fromUV = run(scene(obj, null)), fromWords = run(scene(obj, (String) k[1]));
            for (int i = 0; i < fromUV.length; i++) assertEquals(fromWords[i], fromUV[i], 1e-9, "coordinate " + i + " with warp " + k[1]);
            if (previous != null) {
                double most = 0;
                for (int i = 0; i < previous.length; i++) most = Math.max(most, Math.abs(previous[i] - fromUV[i]));
                assertTrue(most > 1e-4, "a different warp is a different cloth (moved " + most + " m)");
            }
            previous = fromUV;
        }
    }

    @Test
    void textureCoordinatesAreReadPerTriangleCorner() {
        ClothMesh m = ObjReader.parse("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nf 1/1 2/2 3/3 4/4\n", 0);
        // The quad split as a fan from its first corner: (1, 2, 3) and (1, 3, 4).
        assertArrayEquals(new double[] {0, 0, 2, 0, 2, 2, 0, 0, 2, 2, 0, 2}, m.triangleUVs());
        ClothMesh half = ObjReader.parse("h.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1 3 4\n", 0);
        assertNull(half.triangleUVs());
        assertEquals("the face on line 9 has no texture coordinates (vt)", half.whyNoTextureCoordinates());
        MeshFileException e = assertThrows(MeshFileException.class, () -> ObjReader.parse("b.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/2 3/3\n", 0));
        assertTrue(e.getMessage().contains("b.obj:5") && e.getMessage().contains("texture index 2 is out of range"), e.getMessage());
    }

    @Test
    void aMissingWarpSaysWhereItCouldComeFrom() throws IOException {
        String noUV = square(4, (x, y) -> new double[] {x, y}).replaceAll("vt [^\\n]*\\n", "").replaceAll("/\\d+", "");
        PresetException e = assertThrows(PresetException.class, () -> PresetLoader.load(Path.of(scene(noUV, null))));
        assertEquals("fabric.warp", e.field());
        assertTrue(e.problem().contains("square.obj cannot give it: the face on line 26 has no texture coordinates (vt)"), e.getMessage());
        String grid = "{ \"name\": \"g\", \"cloth\": { \"columns\": 4, \"rows\": 4, \"width\": 1, \"height\": 1, \"pins\": [\"top-left\"] },"
                + " \"fabric\": { \"catalogue\": \"denim\" }, \"solver\": { \"mode\": \"XPBD\", \"iterations\": 2, \"dt\": 0.02 } }";
        e = assertThrows(PresetException.class, () -> PresetLoader.parse("g.json", grid));
        assertEquals("fabric.warp", e.field());
        assertTrue(e.problem().contains("a grid cloth has no texture coordinates"), e.getMessage());
        // Texture coordinates that fold a triangle flat give it no direction: named when the scene is built.
        String flat = square(4, (x, y) -> new double[] {x + y, x + y});
        e = assertThrows(PresetException.class, () -> Scene.of(PresetLoader.load(Path.of(scene(flat, null)))));
        assertTrue(e.problem().contains("texture coordinates of zero area"), e.getMessage());
    }
}
