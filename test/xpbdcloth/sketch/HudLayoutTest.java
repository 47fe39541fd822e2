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
        int cases = 0;
        for (float cw : new float[] {7.8f, 9f})
            for (int[] size : SIZES)
                for (boolean sideBySide : new boolean[] {false, true})
                    for (int notice : new int[] {0, 40, 160})
                        for (boolean legend : new boolean[] {false, true})
                            for (boolean help : new boolean[] {false, true}) {
                                HudLayout l = new HudLayout(size[0], size[1], cw, 12, 100, notice, sideBySide ? new int[] {72, 74} : null,
                                        legend, help ? Hud.HELP_TEXTS : null, Hud.HELP_HEADINGS);
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

    /**
     * The help cuts nothing: every text is shown whole, wrapped where its column is too narrow, each row
     * within the column; no text is split across columns and no heading is the last row of a column (at
     * 1280 × 800 the fit entry was cut with the second column nearly empty, and "mouse" sat at the foot of
     * one column with its items at the top of the next).
     */
    @Test
    void theHelpIsWholeAtEverySize() {
        for (float cw : new float[] {7.8f, 9f})
            for (int[] size : SIZES) {
                HudLayout l = new HudLayout(size[0], size[1], cw, 12, 100, 0, null, false, Hud.HELP_TEXTS, Hud.HELP_HEADINGS);
                String at = size[0] + "x" + size[1] + " cw " + cw;
                for (int i = 0; i < Hud.HELP_TEXTS.length; i++) {
                    java.util.List<String> rows = l.helpWrapped.get(i);
                    String joined = String.join(" ", rows).replaceAll("\\s+", " ").trim();
                    assertEquals(Hud.HELP_TEXTS[i].replaceAll("\\s+", " ").trim(), joined, "shown whole at " + at);
                    for (String r : rows) assertTrue(r.length() <= l.helpColumnChars, "'" + r + "' fits its column at " + at);
                    if (l.helpRowOf[i] < 0) continue;
                    assertTrue(l.helpRowOf[i] + rows.size() <= l.helpRows, "not split across columns at " + at);
                    if (Hud.HELP_HEADINGS[i]) assertTrue(l.helpRowOf[i] + 1 < l.helpRows, "heading " + Hud.HELP_TEXTS[i] + " is not a column's last row at " + at);
                }
            }
        HudLayout wide = new HudLayout(1280, 800, 7.8f, 12, 100, 0, null, false, Hud.HELP_TEXTS, Hud.HELP_HEADINGS);
        int wrapped = 0;
        for (java.util.List<String> rows : wide.helpWrapped) if (rows.size() > 1) wrapped++;
        assertTrue(wrapped <= 2, "at 1280 × 800 nearly every entry on one line: " + wrapped + " wrapped");
    }

    @Test
    void longLinesAreCutNotSpilled() {
        assertEquals("abcd…", HudLayout.cut("abcdefgh", 5));
        assertEquals("abc", HudLayout.cut("abc", 5));
        HudLayout l = new HudLayout(800, 600, 7.8f, 12, 200, 0, null, false, null, null);
        assertTrue(l.panel.w <= 800 - 2 * HudLayout.MARGIN);
        assertTrue(l.panelChars * 7.8f + 2 * HudLayout.PAD <= l.panel.w);
    }
}
