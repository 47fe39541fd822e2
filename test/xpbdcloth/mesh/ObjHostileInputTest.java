package xpbdcloth.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * OBJ files from a hostile user: each is refused before it costs minutes or gigabytes, with a message that
 * names the line and says what is wrong in the reader's words, echoing at most a short token of the file.
 */
class ObjHostileInputTest {
    static String refusal(String text) {
        return assertThrows(MeshFileException.class, () -> ObjReader.parse("x.obj", text, 0)).getMessage();
    }

    @Test
    void aFileTooLargeIsRefusedBeforeItIsRead(@TempDir Path dir) throws IOException {
        Path big = dir.resolve("big.obj");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(ObjReader.MAX_FILE_BYTES + 1); // sparse: nothing is written, and nothing may be read
        }
        long t0 = System.nanoTime();
        String message = assertThrows(MeshFileException.class, () -> ObjReader.read(big, 0)).getMessage();
        assertTrue(message.contains("bytes, more than the " + ObjReader.MAX_FILE_BYTES), message);
        assertTrue((System.nanoTime() - t0) / 1e9 < 5, "refused without reading");
    }

    @Test
    void aPolygonWithManyCornersIsCheckedInLinearTimeOrRefused() {
        StringBuilder b = new StringBuilder();
        int n = ObjReader.MAX_CORNERS;
        for (int i = 0; i < n; i++) b.append("v ").append(Math.cos(2 * Math.PI * i / n)).append(' ').append(Math.sin(2 * Math.PI * i / n)).append(" 0\n");
        b.append('f');
        for (int i = 1; i <= n; i++) b.append(' ').append(i);
        assertEquals(n, ObjReader.parse("round.obj", b.toString(), 0).vertexCount(), "a round polygon of the largest size loads");
        String message = refusal(b.append(" 1").toString().replaceFirst("f 1 ", "f 1 1 "));
        assertTrue(message.contains("at most " + n + " corners"), message);
    }

    @Test
    void messagesSayWhatIsWrong() {
        assertTrue(refusal("v 1e308 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3").contains("must be within ±"), "a huge coordinate, not an infinite area");
        assertTrue(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999").contains("vertex index 99999999999 is out of range"), "a long index is out of range");
        assertTrue(refusal("root:x:0:0:root:/root:/bin/bash\nv 0 0 0").startsWith("x.obj:1: is not an OBJ file"), "not OBJ: said, and nothing echoed");
        String echoed = refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nsomething-very-long-that-goes-on-and-on-and-on x");
        assertTrue(echoed.contains("something-very-long-that…") && !echoed.contains("on-and-on-and-on"), "at most a short token: " + echoed);
        assertTrue(refusal("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 3 2 4").contains("face crosses itself"), "a bowtie quad");
        assertEquals(4, ObjReader.parse("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4", 0).vertexCount(), "the same quad in order loads");
        assertEquals(3, ObjReader.parse("bom.obj", "\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3", 0).vertexCount(), "a byte-order mark is read past");
    }

    @Test
    void bytesThatAreNotTextAreNamedByTheirLine(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("latin1.obj");
        byte[] head = "v 0 0 0\nv 1 0 0\n# caf".getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = java.util.Arrays.copyOf(head, head.length + 1);
        bytes[head.length] = (byte) 0xE9; // é in Latin-1, not UTF-8
        Files.write(file, bytes);
        String message = assertThrows(MeshFileException.class, () -> ObjReader.read(file, 0)).getMessage();
        assertTrue(message.contains(":3: is not UTF-8"), message);
    }

    @Test
    void aSymbolicLinkLoopIsSaidToBeOne(@TempDir Path dir) throws IOException {
        Path a = dir.resolve("a.obj"), b = dir.resolve("b.obj");
        Files.createSymbolicLink(a, b);
        Files.createSymbolicLink(b, a);
        String message = assertThrows(MeshFileException.class, () -> ObjReader.read(a, 0)).getMessage();
        assertTrue(message.contains("symbolic link that leads to no file"), message);
    }
}
