package xpbdcloth.pattern;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A garment as it is cut and sewn: named panels and the seams between stretches of their outlines.
 * Validated as a whole: panel names are unique, every seam names panels that exist and positions on their
 * outlines (0 to the corner count), no stretch is empty, and no stretch of outline is sewn twice (two
 * stretches of a panel may share an end, as the side seam and the hem meet at a corner, but not overlap).
 */
public final class Pattern {
    public final String name;
    private final Map<String, Panel> panels = new LinkedHashMap<>();
    private final List<Seam> seams;

    /** @throws IllegalArgumentException naming the panel or seam at fault */
    public Pattern(String name, List<Panel> panels, List<Seam> seams) {
        this.name = name;
        if (panels.isEmpty()) throw new IllegalArgumentException("a pattern needs at least one panel");
        for (Panel p : panels)
            if (this.panels.put(p.name, p) != null) throw new IllegalArgumentException("two panels are named \"" + p.name + "\"");
        this.seams = List.copyOf(seams);
        List<Covered> covered = new ArrayList<>();
        for (Seam s : seams)
            for (Stretch st : new Stretch[] {s.a, s.b}) {
                Panel p = this.panels.get(st.panel);
                if (p == null) throw new IllegalArgumentException("seam \"" + s.name + "\" sews panel \"" + st.panel + "\", which the pattern does not have (it has " + String.join(", ", this.panels.keySet()) + ")");
                int n = p.outline.cornerCount();
                for (double t : new double[] {st.from, st.to})
                    if (!(t >= 0 && t <= n))
                        throw new IllegalArgumentException("seam \"" + s.name + "\": stretch " + st + " runs past the outline's end (positions on panel \"" + p.name + "\" are 0 to " + n + ", its corner count), was " + t);
                double length = st.length(p.outline);
                if (!(length > 1e-9)) throw new IllegalArgumentException("seam \"" + s.name + "\": stretch " + st + " is empty");
                double start = st.backward ? st.arcLengthAt(p.outline, 1) : st.arcLengthAt(p.outline, 0);
                for (Covered c : covered)
                    if (c.panel.equals(p.name) && c.overlaps(start, length, p.outline.length()))
                        throw new IllegalArgumentException("seam \"" + s.name + "\": stretch " + st + " is sewn twice (it overlaps seam \"" + c.seam + "\")");
                covered.add(new Covered(p.name, s.name, start, length));
            }
        for (Seam s : seams)
            if (turn(s.a) == turn(s.b))
                throw new IllegalArgumentException("seam \"" + s.name + "\" sews the face of one panel to the back of the other (both stretches run the same way round their panels' outlines): walk one of them the other way (\"backward\")");
    }

    /**
     * +1 when a stretch runs counter-clockwise in its pattern plane, −1 clockwise. Two panels sewn face to face
     * (their pattern planes' +z the same side of the garment) meet along edges that run opposite ways, as
     * the triangles of one consistently wound surface do.
     */
    private int turn(Stretch st) {
        return (st.backward ? -1 : 1) * (panels.get(st.panel).outline.counterClockwise() ? 1 : -1);
    }

    public List<Panel> panels() { return Collections.unmodifiableList(new ArrayList<>(panels.values())); }

    public Panel panel(String name) { return panels.get(name); }

    public List<Seam> seams() { return seams; }

    /** A stretch of a panel's outline already sewn by a seam: from arc length start, forward. */
    private static final class Covered {
        final String panel, seam;
        final double start, length;

        Covered(String panel, String seam, double start, double length) {
            this.panel = panel;
            this.seam = seam;
            this.start = start;
            this.length = length;
        }

        /** Whether another stretch of the same loop shares more than an end with this one. */
        boolean overlaps(double otherStart, double otherLength, double loop) {
            for (int shift = -1; shift <= 1; shift++) {
                double s = otherStart + shift * loop;
                if (Math.min(start + length, s + otherLength) - Math.max(start, s) > 1e-9 * loop) return true;
            }
            return false;
        }
    }
}
