package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The .usda reader takes what Pixar's library writes, and refuses by name what it does not read, with the line. */
class UsdaReaderTest {
    @TempDir Path dir;

    private Path file(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text, StandardCharsets.UTF_8);
        return p;
    }

    private static final String TRIANGLE = "#usda 1.0\n(\n    metersPerUnit = 0.01\n    timeCodesPerSecond = 30\n)\n\n"
            + "def Xform \"Root\"\n{\n    def Mesh \"Body\"\n    {\n        int[] faceVertexCounts = [3]\n        int[] faceVertexIndices = [0, 1, 2]\n"
            + "        point3f[] points.timeSamples = {\n            1: [(0, 0, 0), (100, 0, 0), (0, 100, 0)],\n            2.5: [(0, 0, 10), (100, 0, 10), (0, 100, 1e1)],\n        }\n"
            + "        texCoord2f[] primvars:st = [(0, 0), (1, 0), (0, 1)] (\n            interpolation = \"faceVarying\"\n        )\n    }\n}\n";

    @Test
    void readsTimeSampledPointsInMetres() throws IOException {
        UsdMeshAnimation m = UsdMeshAnimation.read(file("t.usda", TRIANGLE), null);
        assertEquals("/Root/Body", m.prim);
        assertArrayEquals(new double[] {1, 2.5}, m.timeCodes);
        assertEquals(30, m.timeCodesPerSecond);
        assertArrayEquals(new double[] {0, 0, 0.1, 1, 0, 0.1, 0, 1, 0.1}, m.points[1], 1e-15, "centimetres (metersPerUnit 0.01) to metres");
        assertArrayEquals(new int[] {0, 1, 2}, m.faceVertexIndices);
    }

    /** What Pixar's library wrote in the reference stage of its own Python API: read as written. */
    @Test
    void readsTheLibrarysOwnSpelling() throws IOException {
        Path p = file("pxr.usda", "#usda 1.0\n(\n    defaultPrim = \"World\"\n    doc = \"\"\"a \"triple\" quoted\nstring\"\"\"\n    upAxis = \"Y\"\n)\n\n"
                + "def Xform \"World\" (\n    kind = \"component\"\n    customData = {\n        string note = \"skipped\"\n    }\n)\n{\n"
                + "    def Mesh \"Cloth\"\n    {\n        float3[] extent.timeSamples = {\n            0: [(0, 0, 0), (1, 1, 0)],\n        }\n"
                + "        int[] faceVertexCounts = [3]\n        int[] faceVertexIndices = [0, 1, 2]\n        normal3f[] normals (\n            interpolation = \"vertex\"\n        )\n"
                + "        point3f[] points.timeSamples = {\n            0: [(0, 0, 0), (1, 0, 0), (0, 0.00001, 0)],\n            1: None,\n        }\n"
                + "        rel material:binding = </World/Looks/Red>\n        uniform token[] xformOpOrder = []\n"
                + "        custom double xpbd:fabric:warpModulus = 1.5 (\n            doc = \"E1 t, N/m\"\n        )\n    }\n}\n");
        UsdaReader.Stage s = UsdaReader.read(p);
        assertEquals("a \"triple\" quoted\nstring", s.metadata.get("doc"));
        assertEquals(2, s.prims.size());
        UsdaReader.Prim cloth = s.prims.get(1);
        assertEquals(1.5, cloth.attributes.get("xpbd:fabric:warpModulus").value);
        assertEquals(1, cloth.attributes.get("points").samples.size(), "a None sample blocks the value: nothing kept");
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 1e-5, 0}, (double[]) cloth.attributes.get("points").samples.get(0.0));
    }

    private String refused(String name, String text, String primPath) throws IOException {
        Path p = file(name, text);
        MeshFileException e = assertThrows(MeshFileException.class, () -> UsdMeshAnimation.read(p, primPath));
        assertTrue(e.getMessage().startsWith(p.toString()), e.getMessage());
        return e.getMessage();
    }

    @Test
    void refusesWhatItDoesNotReadByName() throws IOException {
        Path binary = dir.resolve("b.usdc");
        Files.write(binary, "PXR-USDC\0\0\0\0".getBytes(StandardCharsets.ISO_8859_1));
        assertTrue(assertThrows(MeshFileException.class, () -> UsdMeshAnimation.read(binary, null)).getMessage().contains("binary USD"));
        assertTrue(refused("n.usda", "hello\n", null).contains("must begin with '#usda 1.0'"));
        assertTrue(refused("o.usda", "#usda 1.0\nover \"World\"\n{\n}\n", null).contains("'over 'World'' under the root is not a prim definition"));
        assertTrue(refused("r.usda", "#usda 1.0\ndef Xform \"World\" (\n    prepend references = @other.usda@\n)\n{\n}\n", null)
                .contains(":3: prim /World uses references (composition)"));
        assertTrue(refused("i.usda", "#usda 1.0\ndef Mesh \"M\" (\n    instanceable = true\n)\n{\n}\n", null).contains("prim /M uses instanceable"));
        assertTrue(refused("v.usda", "#usda 1.0\ndef Xform \"W\"\n{\n    variantSet \"look\" = {\n    }\n}\n", null).contains("prim /W has a variantSet"));
        assertTrue(refused("c.usda", "#usda 1.0\ndef Mesh \"M\"\n{\n    point3f[] points.connect = </Other.points>\n}\n", null)
                .contains("attribute points of /M is connected"));
        assertTrue(refused("s.usda", TRIANGLE.replace("def Mesh \"Body\"", "def Sphere \"Body\""), "/Root/Body").contains("prim /Root/Body is a Sphere, not a Mesh"));
        assertTrue(refused("x.usda", TRIANGLE.replace("def Xform \"Root\"\n{\n", "def Xform \"Root\"\n{\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"), null)
                .contains("prim /Root has a transform (xformOpOrder)"));
        assertTrue(refused("f.usda", TRIANGLE.replace("[0, 1, 2]", "[0, 1, 3]"), null).contains("faceVertexIndices of /Root/Body must be in [0, 2], has 3"));
        assertTrue(refused("k.usda", TRIANGLE.replace("(0, 100, 1e1)]", "(0, 100, 1e1), (1, 1, 1)]"), null).contains("the count must not change"));
        assertTrue(refused("u.usda", TRIANGLE.replace("[0, 1, 2]\n", "[0, 1, 2\n"), null).contains(":13: expected"), "the line is where the reader stopped");
        assertTrue(refused("a.usda", TRIANGLE.replace("faceVertexCounts = [3]", "faceVertexCounts = [4]"), null).contains("add up to 4 corners but faceVertexIndices has 3"));
        assertTrue(refused("nan.usda", TRIANGLE.replace("(100, 0, 0), (0, 100, 0)]", "(nan, 0, 0), (0, 100, 0)]"), null).contains("point 1 of /Root/Body at time code 1.0 must be finite"));
        assertTrue(refused("none.usda", TRIANGLE, "/Root/Leg").contains("has no prim /Root/Leg; its meshes: /Root/Body"));
    }
}
