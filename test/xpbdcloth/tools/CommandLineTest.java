package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** The command line as a new user types it: options in the wrong place are an error, not ignored. */
class CommandLineTest {

    static String refusal(String... args) {
        CommandLine cli = new CommandLine(new Main());
        StringWriter err = new StringWriter();
        cli.setErr(new PrintWriter(err, true));
        return Main.optionsBeforeCommand(cli, args) ? err.toString() : null;
    }

    @Test
    void optionsBeforeTheCommandAreRefusedWithTheFix() {
        String says = refusal("--scene", "rope", "record", "--frames", "2");
        assertNotNull(says, "refused");
        assertTrue(says.contains("--scene is written before 'record'"), says);
        assertTrue(says.contains("xpbd-cloth record --scene rope ..."), says);
        assertNotNull(refusal("--size", "0x0", "record"));
    }

    @Test
    void optionsInTheirPlaceAreFine() {
        assertNull(refusal("record", "--scene", "rope", "--frames", "2"));
        assertNull(refusal("--scene", "rope"), "options alone open the window with them");
        assertNull(refusal("bench"));
    }
}
