package xpbdcloth.fit;

/** A fit that cannot go on (an unstable rest shape, an observation that is not of the scene), said in words. */
public final class FitException extends RuntimeException {
    public FitException(String message) { super(message); }
}
