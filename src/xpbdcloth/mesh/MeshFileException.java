package xpbdcloth.mesh;

/** A mesh file that cannot be read as a cloth: the message is {@code file:line: problem}. */
public final class MeshFileException extends IllegalArgumentException {
    public final String file;
    /** 1-based; 0 when the problem is the file as a whole. */
    public final int line;
    public final String problem;

    public MeshFileException(String file, int line, String problem) {
        super(file + (line > 0 ? ":" + line : "") + ": " + problem);
        this.file = file;
        this.line = line;
        this.problem = problem;
    }
}
