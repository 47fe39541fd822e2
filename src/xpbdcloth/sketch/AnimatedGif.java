package xpbdcloth.sketch;

import com.madgag.gif.fmsware.AnimatedGifEncoder;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import javax.imageio.ImageIO;

/**
 * Turns a recording's PNG frames into one looping GIF, for sharing a run where a PNG sequence is
 * awkward. GIF delays are whole hundredths of a second, so 60 Hz frames cannot be kept: every second
 * frame is shown for 3/100 s (33 Hz, 10 % slow), at half size so a few seconds stay a few megabytes.
 */
final class AnimatedGif {
    static final int FRAME_STRIDE = 2;
    static final int DELAY_MS = 30;
    static final double SCALE = 0.5;

    private AnimatedGif() {}

    /** Writes the recording's first {@code count} frames to its GIF file; returns the frames used. */
    static int write(ClothApp.Recording recording, int count) throws IOException {
        File gif = recording.gif;
        AnimatedGifEncoder encoder = new AnimatedGifEncoder();
        if (!encoder.start(gif.getPath())) throw new IOException("cannot write " + gif);
        encoder.setRepeat(0);
        encoder.setDelay(DELAY_MS);
        int used = 0;
        for (int i = 1; i <= count; i += FRAME_STRIDE) {
            File png = recording.frame(i);
            BufferedImage frame = ImageIO.read(png);
            if (frame == null) throw new IOException("not an image: " + png);
            encoder.addFrame(scaled(frame));
            used++;
        }
        if (!encoder.finish()) throw new IOException("cannot finish " + gif);
        return used;
    }

    private static BufferedImage scaled(BufferedImage in) {
        int w = Math.max(1, (int) Math.round(in.getWidth() * SCALE)), h = Math.max(1, (int) Math.round(in.getHeight() * SCALE));
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        Graphics2D g = out.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.drawImage(in, 0, 0, w, h, null);
        g.dispose();
        return out;
    }
}
