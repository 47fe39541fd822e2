package xpbdcloth.sketch;

import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/**
 * Keeps JOGL's shutdown report ("X11Util: Open X11 Display Connections: 3" and one line per display, at
 * every exit) off the user's terminal: a standard-error stream that drops whole lines starting with
 * "X11Util" and passes everything else through unchanged. The report is JOGL's own bookkeeping of
 * display connections it leaves to the operating system at exit, not a problem of the sketch.
 */
final class QuietJogl extends OutputStream {
    private final PrintStream out;
    private final java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();

    QuietJogl(PrintStream out) { this.out = out; }

    /** Installs the filter on System.err (once per JVM). */
    static synchronized void install() {
        if (System.err instanceof Marked) return;
        System.setErr(new Marked(new QuietJogl(System.err)));
    }

    private static final class Marked extends PrintStream {
        Marked(OutputStream o) { super(o, true, StandardCharsets.UTF_8); }
    }

    @Override public synchronized void write(int b) {
        if (b != '\n') { bytes.write(b); return; }
        String s = bytes.toString(StandardCharsets.UTF_8);
        bytes.reset();
        if (!s.startsWith("X11Util")) out.println(s);
    }

    @Override public synchronized void flush() {
        // A partial line waits for its end, so a dropped line is dropped whole.
        out.flush();
    }
}
