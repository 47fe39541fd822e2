package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.io.StringWriter;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** Reading, welding and writing OBJ meshes, and every kind of broken file named by file and line. */
class ObjReaderTest {
    static final String QUAD = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    @Test
    void roundTripKeepsPositionsFacesAndGroups() throws IOException {
        ClothMesh mesh = RoundTablecloth.generate(0.7, 5).transformed(1.3, new double[] {10, 20, 30}, new double[] {0.1, 0.2, 0.3});
        StringWriter w = new StringWriter();
        ObjWriter.write(w, mesh, null, "round trip");
        ClothMesh back = ObjReader.parse("trip.obj", w.toString(), 0);
        assertArrayEquals(mesh.positions(), back.positions(), 0.0, "the same doubles, bit for bit");
        assertEquals(mesh.faceCount(), back.faceCount());
        for (int k = 0; k < mesh.faceCount(); k++) assertArrayEquals(mesh.face(k), back.face(k), "face " + k);
        assertEquals(mesh.groups().keySet(), back.groups().keySet());
        for (Map.Entry<String, int[]> g : mesh.groups().entrySet()) assertArrayEquals(g.getValue(), back.group(g.getKey()), g.getKey());
    }

    @Test
    void facesInEveryCornerFormAndNegativeIndices() {
        String text = QUAD + "vt 0 0\nvn 0 0 1\ns off\nusemtl cloth\ng a b\nf 1/1/1 2//1 3/1 -1\n";
        ClothMesh m = ObjReader.parse("forms.obj", text, 0);
        assertArrayEquals(new int[] {0, 1, 2, 3}, m.face(0));
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.triangles(), "a polygon is split as a fan from its first corner");
        assertArrayEquals(new int[] {0, 1, 2, 3}, m.group("a"));
        assertArrayEquals(new int[] {0, 1, 2, 3}, m.group("b"));
    }

    /**
     * Two quads side by side whose shared edge is written twice, the second copy of each vertex moved by
     * d: they weld into one cloth (6 vertices) when d is within the tolerance, and stay cut (8) when not.
     */
    @ParameterizedTest(name = "d = {0} x tolerance")
    @CsvSource({"0.0, 6", "0.5, 6", "0.999, 6", "1.001, 8", "3.0, 8"})
    void weldingMergesOnlyWithinTheTolerance(double fraction, int vertices) {
        double tol = 1e-4, d = fraction * tol;
        String text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                + "v " + (1 + d) + " 0 0\nv 2 0 0\nv 2 1 0\nv 1 " + (1 + d) + " 0\n"
                + "f 1 2 3 4\nf 5 6 7 8\n";
        ClothMesh m = ObjReader.parse("weld.obj", text, tol);
        assertEquals(vertices, m.vertexCount());
        if (vertices == 6) assertArrayEquals(new int[] {1, 4, 5, 2}, m.face(1), "the second quad uses the first one's edge");
    }

    @Test
    void zeroToleranceMergesOnlyIdenticalPositions() {
        String text = QUAD + "v 1 0 0\nv 2 0 0\nv 2 1 0\nv 1 1.0000000001 0\nf 1 2 3 4\nf 5 6 7 8\n";
        assertEquals(7, ObjReader.parse("exact.obj", text, 0).vertexCount());
    }

    @Test
    void unusedVerticesAreDroppedAndTheRestKeepFileOrder() {
        ClothMesh m = ObjReader.parse("unused.obj", "v 9 9 9\n" + QUAD + "f 2 3 4 5\n", 0);
        assertEquals(4, m.vertexCount());
        assertEquals(1.0, m.x(1), 0.0);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "not a number          | v 0 zero 0\\n                                  | bad.obj:1: vertex coordinate y is not a number: \"zero\"",
        "not finite            | v 0 NaN 0\\n                                   | bad.obj:1: vertex coordinate y must be finite, was NaN",
        "too few coordinates   | v 0 1\\n                                       | bad.obj:1: a vertex needs x y z, was 2 numbers",
        "index out of range    | " + "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 4\\n       | bad.obj:4: vertex index 4 is out of range: 3 vertices are defined above this line",
        "index zero            | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 0 1 2\\n          | bad.obj:4: vertex index 0 is out of range",
        "forward reference     | v 0 0 0\\nv 1 0 0\\nf 1 2 3\\nv 0 1 0\\n          | bad.obj:3: vertex index 3 is out of range",
        "two corners           | v 0 0 0\\nv 1 0 0\\nf 1 2\\n                     | bad.obj:3: a face needs at least 3 corners, was 2",
        "not an index          | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 x/1\\n        | bad.obj:4: corner \"x/1\" does not start with a vertex index",
        "repeated corner       | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 1\\n          | bad.obj:4: face is degenerate: corners 1 (1) and 3 (1) are the same vertex",
        "welded corner         | v 0 0 0\\nv 1 0 0\\nv 1 1e-9 0\\nf 1 2 3\\n       | bad.obj:4: face is degenerate: corners 2 (2) and 3 (3) are the same vertex after welding within 1.0E-6 m",
        "collinear             | v 0 0 0\\nv 1 0 0\\nv 2 0 0\\nf 1 2 3\\n          | bad.obj:4: face is degenerate: its area is 0.0 m²",
        "face twice            | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\nf 2 3 1\\n | bad.obj:5: face repeats the face on line 4",
        "non-manifold          | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 0 -1 0\\nv 0 0 1\\nf 1 2 3\\nf 2 1 4\\nf 1 2 5\\n | bad.obj:8: not a manifold: this face's side from (0.0, 0.0, 0.0) to (1.0, 0.0, 0.0) is already a side of the faces on lines 6 and 7",
        "unsupported statement | v 0 0 0\\ncstype bspline\\n                       | bad.obj:2: unsupported statement \"cstype\"",
        "no faces              | v 0 0 0\\nv 1 0 0\\n                            | bad.obj: has no faces (f) or lines (l)",
        "stray point           | v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 5 5 5\\nf 1 2 3\\np 4\\n | bad.obj:6: point (5.0, 5.0, 5.0) is on no face or line",
        "line to itself        | v 0 0 0\\nl 1 1\\n                              | bad.obj:2: line joins a vertex to itself",
    })
    void brokenFilesAreNamedByFileAndLine(String what, String text, String message) {
        MeshFileException e = assertThrows(MeshFileException.class, () -> ObjReader.parse("bad.obj", text.trim().replace("\\n", "\n"), 1e-6), what);
        assertTrue(e.getMessage().startsWith(message.trim()), what + ": " + e.getMessage());
    }
}
