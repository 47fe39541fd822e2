package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Renders each scene through the real P3D sketch, from the installed launcher (what users run), and checks the pictures: the cloth's colours cover a sensible share of
 * the frame and the scene moves between the first and last frame. Needs a display: CI runs the tests
 * under xvfb-run; without one the test is skipped locally and fails under CI=true.
 */
@Tag("slow")
public class RecordingSmokeTest {
    static final int FRAMES = 20;

    /** Runs the installed launcher's record command into {@code out}; returns its log (stdout and stderr). */
    static String record(Path out, String scene, String... extra) throws Exception {
        requireDisplay();
        Path launcher = Path.of(System.getProperty("xpbd.install", "build/install/xpbd-cloth"), "bin", "xpbd-cloth");
        assertTrue(Files.isExecutable(launcher), "installed launcher at " + launcher);
        java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of(launcher.toString(), "record", "--scene", scene,
                "--frames", String.valueOf(FRAMES), "--out", out.toString(), "--size", "640x400"));
        cmd.addAll(java.util.List.of(extra));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.resolve("log.txt").toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "recording finished within 2 minutes");
        String log = Files.readString(out.resolve("log.txt"));
        assertEquals(0, p.exitValue(), "exit code; log:\n" + log);
        return log;
    }

    /** Skips the test without a display, except under CI=true, where it fails: CI must run under xvfb-run. */
    public static void requireDisplay() {
        String display = System.getenv("DISPLAY");
        boolean ci = "true".equals(System.getenv("CI"));
        if (!ci) assumeTrue(display != null && !display.isEmpty(), "no display: run the tests under xvfb-run");
        assertNotNull(display, "CI must run the tests under xvfb-run");
    }

    @ParameterizedTest
    @ValueSource(strings = {"hanging", "corners", "sphere-pass", "rope", "spinning-sphere", "curtain", "flag", "tablecloth", "table", "arm", "drop-fold"})
    void sceneRendersAndMoves(String scene, @org.junit.jupiter.api.io.TempDir Path out) throws Exception {
        String log = record(out, scene);
        File first = out.resolve("frame-0001.png").toFile(), last = out.resolve(String.format("frame-%04d.png", FRAMES)).toFile();
        assertTrue(first.isFile() && last.isFile(), "frames written; log:\n" + log);
        BufferedImage a = ImageIO.read(first), b = ImageIO.read(last);
        assertEquals(640, b.getWidth());
        double cloth = clothShare(b);
        System.out.printf("%s: cloth covers %.1f %% of the last frame, %.2f %% of pixels changed%n", scene, 100 * cloth, 100 * changed(a, b));
        assertTrue(cloth > 0.002 && cloth < 0.8, scene + ": cloth colour share " + cloth);
        assertTrue(changed(a, b) > 0.002, scene + ": the picture changes between first and last frame");
    }

    /** Two recordings of a scene are the same bytes, frame by frame (no wall-clock timing is drawn). */
    @org.junit.jupiter.api.Test
    void recordingsAreByteIdentical(@org.junit.jupiter.api.io.TempDir Path out) throws Exception {
        Path a = Files.createDirectory(out.resolve("a")), b = Files.createDirectory(out.resolve("b"));
        record(a, "sphere-pass");
        record(b, "sphere-pass");
        for (int f = 1; f <= FRAMES; f++) {
            String name = String.format("frame-%04d.png", f);
            assertArrayEquals(Files.readAllBytes(a.resolve(name)), Files.readAllBytes(b.resolve(name)), name);
        }
    }

    /** --gif: every second frame at half size, 30 ms apart, looping; the animation moves. */
    @org.junit.jupiter.api.Test
    void recordingWritesAnAnimatedGif(@org.junit.jupiter.api.io.TempDir Path out) throws Exception {
        Path gif = out.resolve("rope.gif");
        String log = record(out, "rope", "--gif", gif.toString());
        com.madgag.gif.fmsware.GifDecoder d = new com.madgag.gif.fmsware.GifDecoder();
        assertEquals(com.madgag.gif.fmsware.GifDecoder.STATUS_OK, d.read(gif.toString()), "a readable GIF; log:\n" + log);
        assertEquals(FRAMES / 2, d.getFrameCount(), "every second frame");
        assertEquals(320, d.getFrameSize().width, "half size");
        assertEquals(30, d.getDelay(0), "ms per frame");
        assertEquals(0, d.getLoopCount(), "loops forever");
        assertTrue(changed(d.getFrame(0), d.getFrame(FRAMES / 2 - 1)) > 0.002, "the rope moves in the GIF");
    }

    /** --mp4 --fps 30: an H.264 video at the window's size, every second frame, in real time, that decodes and moves. */
    @org.junit.jupiter.api.Test
    void recordingWritesAnMp4(@org.junit.jupiter.api.io.TempDir Path out) throws Exception {
        Path mp4 = out.resolve("rope.mp4");
        String log = record(out, "rope", "--mp4", mp4.toString(), "--fps", "30");
        org.jcodec.api.FrameGrab grab = org.jcodec.api.FrameGrab.createFrameGrab(org.jcodec.common.io.NIOUtils.readableChannel(mp4.toFile()));
        org.jcodec.common.DemuxerTrackMeta meta = grab.getVideoTrack().getMeta();
        assertEquals(FRAMES / 2, meta.getTotalFrames(), "every second frame; log:\n" + log);
        // rope's step is 20 ms, one step a frame: the video lasts what it simulated (at 25 fps, not 30).
        assertEquals(FRAMES * 0.02, meta.getTotalDuration(), 1e-6, "plays in real time (s)");
        assertEquals(640, meta.getVideoCodecMeta().getSize().getWidth(), "the window's width");
        assertEquals(400, meta.getVideoCodecMeta().getSize().getHeight(), "the window's height");
        java.util.List<BufferedImage> frames = new java.util.ArrayList<>();
        org.jcodec.common.model.Picture picture;
        while ((picture = grab.getNativeFrame()) != null) frames.add(org.jcodec.scale.AWTUtil.toBufferedImage(picture));
        assertEquals(FRAMES / 2, frames.size(), "decoded frames");
        double rope = changed(frames.get(0), frames.get(frames.size() - 1));
        assertTrue(rope > 0.002, "the rope moves in the video: " + rope);
        BufferedImage last = ImageIO.read(out.resolve(String.format("frame-%04d.png", FRAMES - 1)).toFile());
        System.out.printf("mp4: %d frames, %d bytes, mean colour error against the PNG %.1f / 255%n", frames.size(), Files.size(mp4), meanError(frames.get(frames.size() - 1), last));
        assertTrue(meanError(frames.get(frames.size() - 1), last) < 5, "the video shows the recorded frame in its colours (lossy, but close; 13.8 with JCodec's full-range levels read as video range)");
    }

    /** Mean absolute difference per colour channel, 0–255. */
    static double meanError(BufferedImage a, BufferedImage b) {
        double sum = 0;
        for (int y = 0; y < a.getHeight(); y++)
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) sum += Math.abs(((p >> shift) & 255) - ((q >> shift) & 255));
            }
        return sum / (3.0 * a.getWidth() * a.getHeight());
    }

    /** Share of pixels in the cloth's front (blue) or back (orange) hue, shaded by any light level. */
    static double clothShare(BufferedImage img) {
        long hits = 0;
        for (int y = 0; y < img.getHeight(); y++)
            for (int x = 0; x < img.getWidth(); x++) {
                int rgb = img.getRGB(x, y), r = (rgb >> 16) & 255, g = (rgb >> 8) & 255, bl = rgb & 255;
                boolean blue = bl > 60 && bl > r + 40 && bl > g + 10;
                boolean orange = r > 80 && r > bl + 60 && g > bl + 20;
                if (blue || orange) hits++;
            }
        return hits / (double) (img.getWidth() * img.getHeight());
    }

    static double changed(BufferedImage a, BufferedImage b) {
        long n = 0;
        for (int y = 0; y < a.getHeight(); y++)
            for (int x = 0; x < a.getWidth(); x++) if (a.getRGB(x, y) != b.getRGB(x, y)) n++;
        return n / (double) (a.getWidth() * a.getHeight());
    }
}
