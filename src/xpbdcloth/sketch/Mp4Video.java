package xpbdcloth.sketch;

import java.awt.image.BufferedImage;
import java.awt.image.ByteLookupTable;
import java.awt.image.LookupOp;
import java.io.File;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.jcodec.api.awt.AWTSequenceEncoder;

/**
 * Turns a recording's PNG frames into an H.264 MP4 (JCodec, pure Java: no ffmpeg needed) at the sketch's
 * resolution, for sharing where a GIF's 256 colours and 33 Hz fall short. Every frame is kept ("60"), or
 * every second one ("30"), and the video's rate is set from the frames' simulated time, so it plays in
 * real time either way.
 * H.264 works on 2 × 2 blocks of colour, so an odd width or height loses its last pixel column or row.
 *
 * <p>JCodec converts RGB to full-range YUV (0–255) but writes no flag saying so, and players, JCodec's own
 * decoder among them, read H.264 as video range (16–235): the frames came back 13 levels in 255 darker
 * on average, crushed blacks. The frames are therefore squeezed into 16–235 before encoding; decoded,
 * they differ from the PNGs by about 3 levels in 255 on average (the encoder's loss; tested below 5).
 */
final class Mp4Video {
    /** Frame rates a recording can be written at: 60 Hz frames, all of them or every second one. */
    static final int[] FRAME_RATES = {30, 60};

    private Mp4Video() {}

    static int checkedFps(int fps) {
        for (int f : FRAME_RATES) if (f == fps) return fps;
        throw new IllegalArgumentException("fps must be 30 or 60 (the recording's frames are 60 Hz), was " + fps);
    }

    /**
     * Writes the recording's first {@code count} frames to its MP4 file; returns the frames used. A frame is
     * {@code frameSeconds} of simulated time (1/60 s where dt divides it, one step where dt is longer), so
     * the video's rate is 1/frameSeconds over the stride, so it plays in real time whatever the scene's timestep.
     */
    static int write(ClothApp.Recording recording, int count, double frameSeconds) throws IOException {
        int stride = 60 / recording.fps;
        int rate = (int) Math.round(1 / (frameSeconds * stride));
        AWTSequenceEncoder encoder = AWTSequenceEncoder.createSequenceEncoder(recording.mp4, Math.max(1, rate));
        int used = 0;
        for (int i = 1; i <= count; i += stride) {
            File png = recording.frame(i);
            BufferedImage frame = ImageIO.read(png);
            if (frame == null) throw new IOException("not an image: " + png);
            encoder.encodeImage(evenSized(frame));
            used++;
        }
        encoder.finish();
        return used;
    }

    /** Each channel 0–255 → 16–235. */
    private static final LookupOp VIDEO_RANGE = videoRange();

    private static LookupOp videoRange() {
        byte[] table = new byte[256];
        for (int c = 0; c < 256; c++) table[c] = (byte) Math.round(16 + c * 219 / 255.0);
        return new LookupOp(new ByteLookupTable(0, table), null);
    }

    /** The frame as 3-byte RGB with even sides and video-range levels, as the encoder and players need. */
    private static BufferedImage evenSized(BufferedImage in) {
        int w = in.getWidth() & ~1, h = in.getHeight() & ~1;
        BufferedImage even = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        even.getGraphics().drawImage(in, 0, 0, null);
        // On the rasters: filtering the images makes a destination of its own choosing, with red and blue swapped.
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        VIDEO_RANGE.filter(even.getRaster(), out.getRaster());
        return out;
    }
}
