package xpbdcloth.sketch;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the HUD's panels go in a window of a given size, computed without drawing so a test can check
 * that nothing overlaps and nothing leaves the window, at any size down to 800 × 600. Text is measured
 * in characters of a monospaced font of width {@code charWidth} pixels; a line longer than its panel is
 * cut (the panel never grows past the window).
 *
 * <p>The rules: the parameter panel top left, the notice as its last line, the two plots bottom left; in side by
 * side the two cloths' labels along the bottom right of the plots, in one row if they fit and else
 * stacked; the strain legend (wireframe) top right if it clears the panel, else under the notice. The
 * help is modal: while it is open it is the only panel, in the fewest columns the height allows, a line
 * too long for its column wrapped onto the next row (never cut), no line split across columns and no
 * heading left at the foot of a column.
 */
final class HudLayout {
    static final int MARGIN = 8, LINE = 18, HELP_LINE = 16, PAD = 8;
    static final int PLOT_W = Hud.PLOT_W, PLOT_H = Hud.PLOT_H;
    static final int LABEL_H = 26, LEGEND_W = 220, LEGEND_H = 44;

    /** x, y, width, height. */
    static final class Rect {
        final float x, y, w, h;

        Rect(float x, float y, float w, float h) { this.x = x; this.y = y; this.w = w; this.h = h; }

        boolean overlaps(Rect o) { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }

        boolean inside(float width, float height) { return x >= 0 && y >= 0 && x + w <= width && y + h <= height; }

        @Override public String toString() { return String.format(java.util.Locale.ROOT, "[%.0f,%.0f %.0fx%.0f]", x, y, w, h); }
    }

    final float width, height, charWidth;
    Rect panel, strainPlot, energyPlot, legend, help;
    /** Baseline of the notice line inside the panel, or -1 for none. */
    float noticeY;
    final Rect[] labels = new Rect[2];
    /** Help: lines per column and the characters that fit in a column. */
    int helpRows, helpColumns, helpColumnChars;
    /** Help: each text's column and first row, and its rows after wrapping. */
    int[] helpColumnOf, helpRowOf;
    List<List<String>> helpWrapped;
    /** Characters that fit on a panel line. */
    int panelChars;

    /**
     * @param panelLines lines of the parameter panel and the longest one's length in characters
     * @param noticeChars 0 for no notice
     * @param labelChars the side-by-side labels' lengths, or null when not side by side
     * @param helpLines 0 when the help is closed; else its lines and longest line
     */
    HudLayout(float width, float height, float charWidth, int panelLines, int panelLongest, int noticeChars, int[] labelChars,
              boolean legendShown, String[] helpTexts, boolean[] helpHeadings) {
        this.width = width;
        this.height = height;
        this.charWidth = charWidth;
        if (helpTexts != null) { layHelp(helpTexts, helpHeadings); return; }
        float maxW = width - 2 * MARGIN;
        // The notice is the panel's last line, so it covers no more of the scene (it used to sit on the pins).
        int longest = steps(Math.max(panelLongest, noticeChars)), rows = panelLines + (noticeChars > 0 ? 1 : 0);
        float pw = Math.min(longest * charWidth + 2 * PAD, maxW);
        panel = new Rect(MARGIN, MARGIN, pw, LINE * rows + 12);
        panelChars = (int) ((pw - 2 * PAD) / charWidth);
        noticeY = noticeChars > 0 ? panel.y + 6 + LINE * panelLines : -1;
        float below = panel.y + panel.h + 6;
        energyPlot = new Rect(MARGIN, height - MARGIN - (PLOT_H + 22), PLOT_W + 8, PLOT_H + 22);
        strainPlot = new Rect(MARGIN, energyPlot.y - 4 - (PLOT_H + 22), PLOT_W + 8, PLOT_H + 22);
        if (labelChars != null) layLabels(labelChars);
        if (legendShown) {
            Rect topRight = new Rect(width - MARGIN - LEGEND_W, MARGIN, LEGEND_W, LEGEND_H);
            legend = topRight.overlaps(panel) ? new Rect(MARGIN, below, LEGEND_W, LEGEND_H) : topRight;
        }
    }

    /** The labels right of the plots: side by side if they fit, else the PBD one above the XPBD one. */
    private void layLabels(int[] chars) {
        float left = energyPlot.x + energyPlot.w + 10, span = width - MARGIN - left;
        float w0 = Math.min(steps(chars[0]) * charWidth + 20, span), w1 = Math.min(steps(chars[1]) * charWidth + 20, span);
        float y = height - MARGIN - LABEL_H;
        if (w0 + 10 + w1 <= span) {
            labels[0] = new Rect(left, y, w0, LABEL_H);
            labels[1] = new Rect(width - MARGIN - w1, y, w1, LABEL_H);
        } else {
            labels[0] = new Rect(left, y - LABEL_H - 4, w0, LABEL_H);
            labels[1] = new Rect(left, y, w1, LABEL_H);
        }
    }

    /**
     * The fewest columns whose rows fit the window's height: each column as wide as the longest text or an
     * equal share of the width, whichever is less; texts wrapped to it; the columns as even as they can be.
     */
    private void layHelp(String[] texts, boolean[] headings) {
        int maxRows = Math.max(1, (int) ((height - 2 * MARGIN - 12) / HELP_LINE));
        int longest = 1;
        for (String t : texts) longest = Math.max(longest, t.length());
        for (int columns = 1; ; columns++) {
            float columnW = Math.min(longest * charWidth + 2 * PAD, (width - 2 * MARGIN) / columns);
            int chars = Math.max(8, (int) ((columnW - 2 * PAD) / charWidth));
            List<List<String>> wrapped = new ArrayList<>();
            int total = 0;
            for (String t : texts) { List<String> w = wrap(t, chars); wrapped.add(w); total += w.size(); }
            // The shortest column height at which the texts, placed in order, fill no more than `columns`.
            for (int rows = (total + columns - 1) / columns; rows <= maxRows; rows++) {
                int[] columnOf = new int[texts.length], rowOf = new int[texts.length];
                if (!place(wrapped, headings, rows, columns, columnOf, rowOf)) continue;
                helpRows = rows;
                helpColumns = columns;
                helpColumnChars = chars;
                helpColumnOf = columnOf;
                helpRowOf = rowOf;
                helpWrapped = wrapped;
                help = new Rect(MARGIN, MARGIN, columnW * columns, HELP_LINE * rows + 12);
                return;
            }
            if (columns >= texts.length) { // cannot happen at 800 × 600 and up; one row a column as a last resort
                helpRows = maxRows; helpColumns = columns; helpColumnChars = chars; helpWrapped = wrapped;
                helpColumnOf = new int[texts.length]; helpRowOf = new int[texts.length];
                help = new Rect(MARGIN, MARGIN, columnW * columns, HELP_LINE * maxRows + 12);
                return;
            }
        }
    }

    /** Places the wrapped texts in order, a text never split across columns nor a heading last in one; false if they need more columns. */
    private static boolean place(List<List<String>> wrapped, boolean[] headings, int rows, int columns, int[] columnOf, int[] rowOf) {
        int column = 0, row = 0;
        for (int i = 0; i < wrapped.size(); i++) {
            int need = wrapped.get(i).size();
            if (need > rows) return false;
            boolean blank = wrapped.get(i).size() == 1 && wrapped.get(i).get(0).isEmpty();
            if (blank && row == 0) { columnOf[i] = column; rowOf[i] = -1; continue; } // no blank line at a column's top
            // A heading goes with the first line under it.
            int keep = headings[i] && i + 1 < wrapped.size() ? need + wrapped.get(i + 1).size() : need;
            if (row + keep > rows) { column++; row = 0; if (blank) { columnOf[i] = column; rowOf[i] = -1; continue; } }
            if (column >= columns) return false;
            columnOf[i] = column;
            rowOf[i] = row;
            row += need;
        }
        return true;
    }

    /**
     * Text broken into lines of at most n characters, at spaces where it can; continuation lines start
     * under the description of a key entry ("m      PBD …"), else two characters in.
     */
    static List<String> wrap(String text, int n) {
        java.util.regex.Matcher key = java.util.regex.Pattern.compile("^\\S{1,6} +").matcher(text);
        int indent = key.find() && key.end() <= 8 && key.end() < n / 2 ? key.end() : 2;
        String pad = " ".repeat(indent);
        List<String> out = new ArrayList<>();
        String rest = text;
        while (rest.length() > n) {
            int at = rest.lastIndexOf(' ', n);
            if (at <= indent + (n - indent) / 3) at = n; // no space near enough: break inside the word
            out.add(rest.substring(0, at));
            rest = pad + rest.substring(at).trim();
        }
        out.add(rest);
        return out;
    }

    /** Every panel laid out (nulls left out). */
    List<Rect> all() {
        List<Rect> out = new ArrayList<>();
        for (Rect r : new Rect[] {panel, strainPlot, energyPlot, legend, help, labels[0], labels[1]}) if (r != null) out.add(r);
        return out;
    }

    /** Widths in steps of 5 characters, so panels do not twitch as the numbers in them change length. */
    static int steps(int chars) { return (chars + 4) / 5 * 5; }

    /** s cut to n characters, with "…" when cut. */
    static String cut(String s, int n) {
        if (s.length() <= n) return s;
        return n <= 1 ? "" : s.substring(0, n - 1) + "…";
    }
}
