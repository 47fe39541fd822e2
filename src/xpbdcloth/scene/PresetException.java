package xpbdcloth.scene;

/**
 * A preset that cannot be used, with the file, the field (a JSON path such as {@code cloth.columns}) and
 * the problem. It is an {@link IllegalArgumentException}: bad input, never a crash, and nothing running
 * is touched.
 */
public final class PresetException extends IllegalArgumentException {
    private final String file, field, problem;

    public PresetException(String file, String field, String problem) {
        super(printable(file) + ": " + printable(field) + ": " + printable(problem));
        this.file = file;
        this.field = printable(field);
        this.problem = printable(problem);
    }

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
