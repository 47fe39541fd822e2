package processing.utils;

/**
 * Stand-in for the one class of Processing's {@code org.processing:utils} (not on Maven Central) that its
 * preprocessor needs: it names this exception in {@code throws} clauses and never constructs it.
 */
public class SketchException extends Exception {
    public SketchException(String message) { super(message); }
}
