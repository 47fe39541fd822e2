package xpbdcloth.mesh;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * Reads USD's text form (.usda) as far as a flattened stage of plain prims goes: the layer's metadata,
 * {@code def} prims with their types, and their attributes' default values and time samples (numbers,
 * tuples and arrays of them as flat doubles; strings and tokens as text). What it does not read it refuses
 * by name rather than misreading: a binary crate file (.usdc), composition (references, payloads,
 * inherits, specializes, variants, instancing), {@code over} and {@code class} specs, attribute
 * connections and splines. Grammar: Pixar's Sdf text format (openusd.org, "USD File Formats"; the
 * grammar in pxr/usd/sdf/textFileFormat). Errors are {@code file:line: problem}.
 */
public final class UsdaReader {
    /** The largest file read: a thousand frames of a 128² cloth, with room. */
    public static final long MAX_FILE_BYTES = 1L << 30;

    private static final Set<String> COMPOSITION = Set.of("references", "payload", "inherits", "specializes", "variants", "variantSets", "instanceable");
    private static final Set<String> LIST_OPS = Set.of("prepend", "append", "add", "delete", "reorder");

    /** An attribute: its declared type, its default value (null if none) and its time samples by time code. */
    public static final class Attribute {
        public final String type;
        public Object value;
        public final TreeMap<Double, Object> samples = new TreeMap<>();

        Attribute(String type) { this.type = type; }
    }

    /** A prim: its path, its type name ("" for a typeless def) and its attributes by name. */
    public static final class Prim {
        public final String path, type;
        public final Map<String, Attribute> attributes = new LinkedHashMap<>();
        /** Line where the prim is declared. */
        public final int line;

        Prim(String path, String type, int line) { this.path = path; this.type = type; this.line = line; }
    }

    /** A stage read: its metadata (numbers as Double, text as String) and its prims in file order. */
    public static final class Stage {
        public final String file;
        public final Map<String, Object> metadata = new LinkedHashMap<>();
        public final List<Prim> prims = new ArrayList<>();

        Stage(String file) { this.file = file; }

        /** A metadata number, or {@code otherwise} when the layer does not set it. */
        public double number(String key, double otherwise) {
            Object v = metadata.get(key);
            return v instanceof Double ? (Double) v : otherwise;
        }
    }

    private final String file;
    private final BufferedReader in;
    private int line = 1, peeked = -2;
    private String token;
    private boolean tokenIsString;

    private UsdaReader(String file, BufferedReader in) {
        this.file = file;
        this.in = in;
    }

    /** Reads a .usda file, or a {@link MeshFileException} naming the file, the line and what is wrong. */
    public static Stage read(Path path) {
        String file = path.toString();
        try {
            if (!Files.exists(path)) throw new MeshFileException(file, 0, Files.exists(path, LinkOption.NOFOLLOW_LINKS) ? "is a link that leads nowhere" : "does not exist");
            if (!Files.isRegularFile(path)) throw new MeshFileException(file, 0, "is not a file");
            long size = Files.size(path);
            if (size > MAX_FILE_BYTES) throw new MeshFileException(file, 0, "is " + size + " bytes, more than the " + MAX_FILE_BYTES + " a USD file read here may have");
            try (InputStream raw = Files.newInputStream(path)) {
                byte[] head = raw.readNBytes(8);
                String magic = new String(head, StandardCharsets.ISO_8859_1);
                if (magic.startsWith("PXR-USDC"))
                    throw new MeshFileException(file, 0, "is binary USD (a .usdc crate file); this reads USD's text form: convert it with `usdcat " + path.getFileName() + " -o out.usda`");
                if (magic.startsWith("PK"))
                    throw new MeshFileException(file, 0, "is a USDZ package (a zip); unzip it and read the .usda or convert its .usdc with usdcat");
            }
            try (BufferedReader r = Files.newBufferedReader(path, StandardCharsets.UTF_8)) {
                return parse(file, r);
            }
        } catch (java.nio.charset.MalformedInputException e) {
            throw new MeshFileException(file, 0, "is not UTF-8 text, so not USD's text form");
        } catch (IOException e) {
            throw new MeshFileException(file, 0, "cannot be read: " + e.getMessage());
        }
    }

    /** Reads USD text from a reader (a file's, or a resource's), {@code file} naming it in errors. */
    public static Stage parse(String file, java.io.Reader text) throws IOException {
        BufferedReader r = text instanceof BufferedReader ? (BufferedReader) text : new BufferedReader(text);
        return new UsdaReader(file, r).stage();
    }

    private Stage stage() throws IOException {
        String first = in.readLine();
        if (first == null || !first.trim().startsWith("#usda 1.0"))
            throw fail("is not USD's text form: it must begin with '#usda 1.0', began with " + shown(first));
        line = 2;
        Stage stage = new Stage(file);
        next();
        if ("(".equals(token) && !tokenIsString) metadata(stage.metadata, null);
        while (token != null) prim(stage, "");
        return stage;
    }

    /** Reads '(' … ')' after the '(' token; keeps scalar entries in {@code into}; refuses composition on a prim. */
    private void metadata(Map<String, Object> into, String prim) throws IOException {
        next();
        while (!is(")")) {
            if (token == null) throw fail("the metadata opened with '(' is not closed");
            if (tokenIsString) { into.put("doc", token); next(); continue; }
            String key = token;
            if (LIST_OPS.contains(key)) { next(); key = token; }
            if (prim != null && COMPOSITION.contains(key))
                throw fail("prim " + prim + " uses " + key + " (composition), which this reader does not follow; flatten the stage first: `usdcat --flatten in.usda -o out.usda`");
            next();
            expect("=");
            Object v = value();
            if (into != null && (v instanceof Double || v instanceof String)) into.put(key, v);
            if (is(";")) next();
        }
        next();
    }

    private void prim(Stage stage, String parent) throws IOException {
        int at = line;
        String specifier = token;
        if ("over".equals(specifier) || "class".equals(specifier)) {
            next();
            if (!tokenIsString && token != null) next();
            throw fail("'" + specifier + " " + shown(token) + "' under " + (parent.isEmpty() ? "the root" : parent)
                    + " is not a prim definition ('def'): this reader does not compose layers or classes; flatten the stage first: `usdcat --flatten in.usda -o out.usda`");
        }
        if (!"def".equals(specifier)) throw fail("expected a prim ('def Type \"name\"'), found " + shown(specifier));
        next();
        String type = "";
        if (!tokenIsString) { type = token; next(); }
        if (!tokenIsString) throw fail("expected the prim's name in quotes after 'def " + type + "', found " + shown(token));
        String path = parent + "/" + token;
        Prim p = new Prim(path, type, at);
        stage.prims.add(p);
        next();
        if (is("(")) metadata(null, path);
        expect("{");
        while (!is("}")) {
            if (token == null) throw fail("prim " + path + " opened with '{' is not closed");
            if ("def".equals(token) || "over".equals(token) || "class".equals(token)) prim(stage, path);
            else if ("variantSet".equals(token)) throw fail("prim " + path + " has a variantSet, which this reader does not follow; flatten the stage first: `usdcat --flatten`");
            else property(p);
        }
        next();
    }

    private void property(Prim p) throws IOException {
        while ("custom".equals(token) || "uniform".equals(token) || "varying".equals(token) || "config".equals(token)) next();
        if ("rel".equals(token)) { // relationships (material bindings, say) name other prims: nothing here needs them
            next();
            next();
            if (is("=")) { next(); value(); }
            if (is("(")) metadata(null, null);
            return;
        }
        String type = token;
        next();
        if (is("[")) { next(); expect("]"); type += "[]"; }
        String name = token;
        if (name == null || tokenIsString) throw fail("prim " + p.path + ": expected an attribute name after its type " + type + ", found " + shown(name));
        next();
        String suffix = null;
        int dot = name.lastIndexOf('.');
        if (dot > 0) { suffix = name.substring(dot + 1); name = name.substring(0, dot); }
        if ("connect".equals(suffix)) throw fail("attribute " + name + " of " + p.path + " is connected to another (.connect), which this reader does not follow");
        if ("spline".equals(suffix)) throw fail("attribute " + name + " of " + p.path + " is a spline, which this reader does not evaluate; bake it to time samples");
        final String declared = type;
        Attribute a = p.attributes.computeIfAbsent(name, n -> new Attribute(declared));
        if (is("=")) {
            next();
            if ("timeSamples".equals(suffix)) samples(a, p.path + "." + name);
            else a.value = value();
        }
        if (is("(")) metadata(null, null);
    }

    private void samples(Attribute a, String where) throws IOException {
        expect("{");
        while (!is("}")) {
            if (token == null) throw fail("the time samples of " + where + " are not closed");
            double code = number(token, "a time code of " + where);
            next();
            expect(":");
            Object v = value();
            if (v != null) a.samples.put(code, v);
            if (is(",")) next();
        }
        next();
    }

    /** A value: a number (Double), a string or token (String), None (null), or a tuple or array (a flat double[] of numbers, else a List). */
    private Object value() throws IOException {
        if (token == null) throw fail("a value is missing at the end of the file");
        if (tokenIsString) { String s = token; next(); return s; }
        if (is("[") || is("(")) return sequence(is("[") ? "]" : ")");
        if (is("{")) { skipBalanced("{", "}"); return null; }
        if (is("None")) { next(); return null; }
        if (token.startsWith("@") || token.startsWith("<")) { String s = token; next(); return s; }
        char c = token.charAt(0);
        if (Character.isDigit(c) || c == '-' || c == '+' || c == '.' || is("inf") || is("nan")) {
            double v = number(token, "a number");
            next();
            return v;
        }
        String s = token; // an identifier used as a value: true, false, a token without quotes
        next();
        return s;
    }

    private Object sequence(String close) throws IOException {
        int opened = line;
        next();
        double[] numbers = new double[16];
        int n = 0;
        List<Object> other = null;
        while (!is(close)) {
            if (token == null) throw fail("a list opened on line " + opened + " is not closed with '" + close + "'");
            if (!tokenIsString && Character.isLetter(token.charAt(0)) && !is("None") && !is("true") && !is("false") && !is("inf") && !is("nan"))
                throw fail("expected a value or '" + close + "' in the list opened on line " + opened + ", found " + shown(token));
            Object v = value();
            if (v instanceof Double && other == null) {
                if (n == numbers.length) numbers = java.util.Arrays.copyOf(numbers, 2 * n);
                numbers[n++] = (Double) v;
            } else if (v instanceof double[] && other == null) {
                double[] t = (double[]) v;
                if (n + t.length > numbers.length) numbers = java.util.Arrays.copyOf(numbers, Math.max(2 * numbers.length, n + t.length));
                System.arraycopy(t, 0, numbers, n, t.length);
                n += t.length;
            } else {
                if (other == null) other = new ArrayList<>();
                other.add(v);
            }
            if (is(",")) next();
        }
        next();
        return other != null ? other : java.util.Arrays.copyOf(numbers, n);
    }

    private void skipBalanced(String open, String close) throws IOException {
        int depth = 0;
        do {
            if (token == null) throw fail("'" + open + "' is not closed");
            if (!tokenIsString && token.equals(open)) depth++;
            else if (!tokenIsString && token.equals(close)) depth--;
            next();
        } while (depth > 0);
    }

    private double number(String s, String what) {
        if (s.equals("inf")) return Double.POSITIVE_INFINITY;
        if (s.equals("-inf")) return Double.NEGATIVE_INFINITY;
        if (s.equals("nan")) return Double.NaN;
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException e) {
            throw fail(what + " must be a number, was " + shown(s));
        }
    }

    private boolean is(String s) { return !tokenIsString && s.equals(token); }

    private void expect(String s) throws IOException {
        if (!is(s)) throw fail("expected '" + s + "', found " + shown(token));
        next();
    }

    // --- the tokenizer: punctuation, quoted strings, numbers, identifiers (with : and . inside), @asset@, <path>; # comments ---

    private int read() throws IOException {
        int c = peeked != -2 ? peeked : in.read();
        peeked = -2;
        if (c == '\n') line++;
        return c;
    }

    private int peek() throws IOException {
        if (peeked == -2) peeked = in.read();
        return peeked;
    }

    private void next() throws IOException {
        tokenIsString = false;
        int c;
        while (true) {
            c = read();
            if (c == '#') { while (c != '\n' && c != -1) c = read(); continue; }
            if (c == -1) { token = null; return; }
            if (!Character.isWhitespace(c)) break;
        }
        if ("()[]{}=,:;".indexOf(c) >= 0) { token = String.valueOf((char) c); return; }
        StringBuilder b = new StringBuilder();
        if (c == '"' || c == '\'') { string((char) c, b); token = b.toString(); tokenIsString = true; return; }
        if (c == '@' || c == '<') {
            char end = c == '@' ? '@' : '>';
            b.append((char) c);
            int d;
            while ((d = read()) != end) { if (d == -1 || d == '\n') throw fail("an " + (end == '@' ? "asset path" : "object path") + " is not closed"); b.append((char) d); }
            token = b.append(end).toString();
            return;
        }
        b.append((char) c);
        while (true) {
            int d = peek();
            if (d == -1 || Character.isWhitespace(d) || "()[]{}=,;\"'#".indexOf(d) >= 0) break;
            if (d == ':' && !(Character.isLetter(b.charAt(0)) || b.charAt(0) == '_')) break; // "3:" is a time code and its colon
            b.append((char) read());
            if (b.length() > 4096) throw fail("a word longer than 4096 characters: not USD text");
        }
        token = b.toString();
    }

    private void string(char quote, StringBuilder b) throws IOException {
        boolean triple = false;
        if (peek() == quote) {
            read();
            if (peek() != quote) return; // ""
            read();
            triple = true;
        }
        int start = line;
        while (true) {
            int c = read();
            if (c == -1) throw new MeshFileException(file, start, "a string opened here is not closed");
            if (c == '\\') { int e = read(); b.append(e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : (char) e); continue; }
            if (c == quote) {
                if (!triple) return;
                if (peek() == quote) { read(); if (peek() == quote) { read(); return; } b.append(quote); }
                b.append(quote);
                continue;
            }
            if (c == '\n' && !triple) throw new MeshFileException(file, start, "a string opened here runs past the end of its line");
            b.append((char) c);
        }
    }

    private MeshFileException fail(String problem) { return new MeshFileException(file, line, problem); }

    private static String shown(String s) {
        if (s == null) return "the end of the file";
        return "'" + (s.length() > 24 ? s.substring(0, 24) + "…" : s) + "'";
    }
}
