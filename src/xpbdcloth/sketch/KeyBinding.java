package xpbdcloth.sketch;

import java.util.function.Consumer;
import java.util.function.Function;

/**
 * One key: what it does, the help text, and the piece of state it claims to change (so a test can press
 * every key and check the claim).
 */
public final class KeyBinding {
    public final char key;
    public final String help;
    final Consumer<SketchState> action;
    final Function<SketchState, Object> changes;

    KeyBinding(char key, String help, Consumer<SketchState> action, Function<SketchState, Object> changes) {
        this.key = key;
        this.help = help;
        this.action = action;
        this.changes = changes;
    }

    public void press(SketchState s) { action.accept(s); }

    /** The state this key claims to change, as a comparable value. */
    public Object observe(SketchState s) { return changes.apply(s); }
}
