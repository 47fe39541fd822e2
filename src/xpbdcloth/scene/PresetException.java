package xpbdcloth.scene;

/**
 * A preset that cannot be used, with the file, the field (a JSON path such as {@code cloth.columns}) and
 * the problem. It is an {@link IllegalArgumentException}: bad input, never a crash, and nothing running
 * is touched.
 */
public final class PresetException extends IllegalArgumentException {
    private final String file, field, problem;
    /** Every problem found in the file, this one first (a preset's independent fields are all read). */
    private final java.util.List<PresetException> all;

    public PresetException(String file, String field, String problem) {
        super(printable(file) + ": " + printable(field) + ": " + printable(problem));
        this.file = file;
        this.field = printable(field);
        this.problem = printable(problem);
        this.all = java.util.List.of(this);
    }

    /** Several problems of one file: the first gives the field and problem, the message lists them all, a line each. */
    PresetException(java.util.List<PresetException> problems) {
        super(joined(problems));
        PresetException first = problems.get(0);
        this.file = first.file;
        this.field = first.field;
        this.problem = first.problem;
        this.all = java.util.List.copyOf(problems);
    }

    private static String joined(java.util.List<PresetException> problems) {
        StringBuilder b = new StringBuilder();
        for (PresetException p : problems) b.append(b.length() == 0 ? "" : "\n").append(p.getMessage());
        return b.toString();
    }

    /** Each problem found, in the order the file reads; one for a file that failed early (its syntax, its kind). */
    public java.util.List<PresetException> all() { return all; }

    /** Control characters from a hostile file (a field name with an escape sequence) reach no terminal raw. */
    static String printable(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c == 0x7f || (c >= 0x80 && c < 0xa0)) b.append(String.format("\\u%04x", (int) c));
            else b.append(c);
        }
        return b.toString();
    }

    public String file() { return file; }
    public String field() { return field; }
    public String problem() { return problem; }
}
