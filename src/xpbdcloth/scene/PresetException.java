package xpbdcloth.scene;

/**
 * A preset that cannot be used, with the file, the field (a JSON path such as {@code cloth.columns}) and
 * the problem. It is an {@link IllegalArgumentException}: bad input, never a crash, and nothing running
 * is touched.
 */
public final class PresetException extends IllegalArgumentException {
    private final String file, field, problem;

    public PresetException(String file, String field, String problem) {
        super(file + ": " + field + ": " + problem);
        this.file = file;
        this.field = field;
        this.problem = problem;
    }

    public String file() { return file; }
    public String field() { return field; }
    public String problem() { return problem; }
}
