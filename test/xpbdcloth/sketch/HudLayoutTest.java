package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The HUD's panels at every window size the sketch supports (down to 800 × 600), in every state (side by
 * side, a notice, the strain legend, the help): each inside the window, none overlapping another. Text
 * is measured at DejaVu Sans Mono's 7.8 px per character at 13 px, and at a wider fallback font's 9 px.
 */
class HudLayoutTest {
    static final int[][] SIZES = {{800, 600}, {900, 600}, {1024, 768}, {1280, 800}, {1920, 1080}};

    @Test
    void nothingOverlapsAndNothingLeavesTheWindow() {
        int helpLongest = 0;
        for (KeyBinding k : KeyBindings.all()) helpLongest = Math.max(helpLongest, Hud.HELP_KEY_CHARS + k.help.length());
        int helpLines = KeyBindings.all().size() + Hud.MOUSE_HELP.length + 3;
        int cases = 0;
        for (float cw : new float[] {7.8f, 9f})
            for (int[] size : SIZES)
                for (boolean sideBySide : new boolean[] {false, true})
                    for (int notice : new int[] {0, 40, 160})
                        for (boolean legend : new boolean[] {false, true})
                            for (boolean help : new boolean[] {false, true}) {
                                HudLayout l = new HudLayout(size[0], size[1], cw, 12, 100, notice, sideBySide ? new int[] {72, 74} : null,
                                        legend, help ? helpLines : 0, helpLongest);
                                List<HudLayout.Rect> rects = l.all();
                                String where = size[0] + "x" + size[1] + " cw " + cw + (sideBySide ? " side by side" : "") + " notice " + notice
                                        + (legend ? " legend" : "") + (help ? " help" : "") + ": " + rects;
                                for (HudLayout.Rect r : rects) assertTrue(r.inside(size[0], size[1]), "inside the window, " + r + " at " + where);
                                for (int i = 0; i < rects.size(); i++)
                                    for (int j = i + 1; j < rects.size(); j++)
                                        assertFalse(rects.get(i).overlaps(rects.get(j)), rects.get(i) + " overlaps " + rects.get(j) + " at " + where);
                                if (help) assertTrue(l.helpColumnChars >= 30, "help stays readable (" + l.helpColumnChars + " characters a column) at " + where);
                                cases++;
                            }
        assertEquals(2 * 5 * 2 * 3 * 2 * 2, cases);
    }

    @Test
    void longLinesAreCutNotSpilled() {
        assertEquals("abcd…", HudLayout.cut("abcdefgh", 5));
        assertEquals("abc", HudLayout.cut("abc", 5));
        HudLayout l = new HudLayout(800, 600, 7.8f, 12, 200, 0, null, false, 0, 0);
        assertTrue(l.panel.w <= 800 - 2 * HudLayout.MARGIN);
        assertTrue(l.panelChars * 7.8f + 2 * HudLayout.PAD <= l.panel.w);
    }
}
