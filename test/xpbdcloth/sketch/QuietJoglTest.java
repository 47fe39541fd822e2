package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The standard-error filter drops JOGL's display report, whole lines only, and nothing else. */
class QuietJoglTest {
    @Test
    void dropsOnlyX11UtilLines() {
        ByteArrayOutputStream sink = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(new QuietJogl(new PrintStream(sink, true, StandardCharsets.UTF_8)), true, StandardCharsets.UTF_8);
        err.println("xpbd-cloth: a real error");
        err.println("X11Util: Open X11 Display Connections: 3");
        err.println("X11Util: Open[0]: NamedX11Display[:99, 0x7f, refCount 1]");
        err.print("partial ");
        err.println("line with X11Util inside");
        err.println("α and ‖ survive");
        assertEquals("xpbd-cloth: a real error\npartial line with X11Util inside\nα and ‖ survive\n", sink.toString(StandardCharsets.UTF_8).replace("\r\n", "\n"));
    }
}
