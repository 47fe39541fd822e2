package xpbdcloth.usd;

/**
 * How values are spelt in USD's text format (.usda): numbers in Java's shortest round-trip form (a
 * {@code float} attribute gets the float nearest the double, so reading it back gives that float
 * exactly), strings quoted with their quotes and backslashes escaped, prim names checked against
 * USD's identifier rule. Pixar, "USD File Formats" and the Sdf text grammar (openusd.org).
 */
final class UsdaText {
    private UsdaText() {}

    /** A float value as usda reads it: "0", "0.25", "1.0E-5" (the trailing ".0" of a whole number dropped). */
    static StringBuilder appendFloat(StringBuilder b, double v) {
        return trimmed(b, Float.toString((float) v));
    }

    /** A double value as usda reads it, exactly. */
    static StringBuilder appendDouble(StringBuilder b, double v) {
        return trimmed(b, Double.toString(v));
    }

    private static StringBuilder trimmed(StringBuilder b, String s) {
        return s.endsWith(".0") ? b.append(s, 0, s.length() - 2) : b.append(s);
    }

    /** "text" with " and \ escaped and line breaks as \n. */
    static String quoted(String s) {
        StringBuilder b = new StringBuilder(s.length() + 2).append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '"' || c == '\\') b.append('\\').append(c);
            else if (c == '\n') b.append("\\n");
            else if (c == '\r') b.append("\\r");
            else if (c == '\t') b.append("\\t");
            else b.append(c);
        }
        return b.append('"').toString();
    }

    /** A prim name from any label: letters, digits and underscores, not starting with a digit (USD's identifier rule). */
    static String identifier(String label) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < label.length(); i++) {
            char c = label.charAt(i);
            b.append(c < 128 && (Character.isLetterOrDigit(c) || c == '_') ? c : '_');
        }
        if (b.length() == 0 || Character.isDigit(b.charAt(0))) b.insert(0, '_');
        return b.toString();
    }
}
