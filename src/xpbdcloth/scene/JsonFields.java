package xpbdcloth.scene;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * Strict reading of the project's JSON files (presets, the fabric catalogue, garment patterns): each value
 * with its path, typed access whose problems are {@link PresetException}s naming the file and the field, and
 * the problems that let reading go on collected, so a file's every problem is reported at once.
 */
abstract class JsonFields {
    static final ObjectMapper JSON = new ObjectMapper().enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);

    final String file;

    JsonFields(String file) { this.file = file; }

    static JsonNode readJson(String file, String text) {
        if (text.isBlank()) throw new PresetException(file, "(file)", "is empty");
        try {
            return JSON.readerFor(JsonNode.class).with(com.fasterxml.jackson.databind.DeserializationFeature.FAIL_ON_TRAILING_TOKENS).readValue(text);
        } catch (JsonProcessingException e) {
            String where = e.getLocation() == null ? "" : " at line " + e.getLocation().getLineNr() + " column " + e.getLocation().getColumnNr();
            throw new PresetException(file, "(syntax)", "not valid JSON" + where + ": " + inOurWords(e.getOriginalMessage()));
        }
    }

    /** Jackson's message without its advice to switch on parser features, which a preset author cannot. */
    static String inOurWords(String jackson) {
        if (jackson.contains("ALLOW_NON_NUMERIC_NUMBERS"))
            return "NaN and Infinity are not numbers in JSON (and no field takes them): give a finite number";
        return jackson.replaceAll(":? *(?:enable|use) `?JsonReadFeature\\.[A-Z_]+`?[^\\n]*", "");
    }

    /** A JSON value and its path, for messages. */
    static final class Node {
        final JsonNode json;
        final String path;

        Node(JsonNode json, String path) {
            this.json = json;
            this.path = path;
        }

        String child(String name) { return path.isEmpty() ? name : path + "." + name; }
    }

    /**
     * Problems found so far that let reading go on: a number or a count outside its range is noted and read
     * as the nearest value inside it, so the fields after it are still checked and a file's every problem
     * is reported at once, not one per attempt.
     */
    final List<PresetException> found = new ArrayList<>();

    PresetException fail(String field, String problem) {
        return new PresetException(file, field.isEmpty() ? "(root)" : field, problem);
    }

    /** The problems found, as one exception (itself when there is one). */
    PresetException everything() {
        return found.size() == 1 ? found.get(0) : new PresetException(found);
    }

    /** Reads a whole file: everything it reads, or every problem found in it at once. */
    <T> T whole(java.util.function.Supplier<T> read) {
        T t = part(read);
        if (!found.isEmpty()) throw everything();
        return t;
    }

    /**
     * Reads a part of the preset that does not depend on another: a problem that stops it is noted and the
     * part comes back null, so the parts after it are still read.
     */
    <T> T part(java.util.function.Supplier<T> read) {
        try {
            return read.get();
        } catch (PresetException e) {
            found.addAll(e.all());
            return null;
        }
    }

    // ---- typed access with messages ----

    void object(Node n, Set<String> allowed) {
        if (!n.json.isObject()) throw fail(n.path, "must be an object, was " + describe(n.json));
        only(n, allowed);
    }

    void only(Node n, Set<String> allowed) {
        for (Iterator<String> it = n.json.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!allowed.contains(f))
                throw fail(n.child(f), "unknown field; allowed here: " + String.join(", ", new TreeSet<>(allowed)));
        }
    }

    Node required(Node n, String name) {
        JsonNode j = n.json.get(name);
        if (j == null || j.isNull()) throw fail(n.child(name), "is missing");
        return new Node(j, n.child(name));
    }

    Node optional(Node n, String name) {
        JsonNode j = n.json.get(name);
        return j == null || j.isNull() ? null : new Node(j, n.child(name));
    }

    /** An array of at most {@code max} entries. */
    List<Node> array(Node n, int max) {
        List<Node> out = array(n);
        if (out.size() > max) throw fail(n.path, "has " + out.size() + " entries; at most " + max + " are allowed");
        return out;
    }

    List<Node> array(Node n) {
        if (!n.json.isArray()) throw fail(n.path, "must be an array, was " + describe(n.json));
        List<Node> out = new ArrayList<>();
        for (int i = 0; i < n.json.size(); i++) out.add(new Node(n.json.get(i), n.path + "[" + i + "]"));
        return out;
    }

    String string(Node n) {
        if (!n.json.isTextual()) throw fail(n.path, "must be a string, was " + describe(n.json));
        return n.json.asText();
    }

    boolean bool(Node n) {
        if (!n.json.isBoolean()) throw fail(n.path, "must be true or false, was " + describe(n.json));
        return n.json.asBoolean();
    }

    double number(Node n, Limits.Range range) {
        if (!n.json.isNumber()) throw fail(n.path, "must be a number, was " + describe(n.json));
        double v = n.json.asDouble();
        if (!Double.isFinite(v)) throw fail(n.path, "must be in " + range.text() + (range.unit.isEmpty() ? "" : " " + range.unit) + ", was " + n.json.asText());
        if (!range.contains(v)) {
            found.add(fail(n.path, "must be in " + range.text() + (range.unit.isEmpty() ? "" : " " + range.unit) + ", was " + n.json.asText()));
            return range.clamp(v);
        }
        return v;
    }

    int integer(Node n, Limits.Range range) {
        int v = integer(n);
        if (!range.contains(v)) {
            found.add(fail(n.path, "must be in " + range.text() + ", was " + v));
            return (int) range.clamp(v);
        }
        return v;
    }

    int integer(Node n) {
        if (n.json.isIntegralNumber() && !n.json.canConvertToInt())
            throw fail(n.path, "is too large: must be a whole number within ±" + Integer.MAX_VALUE + ", was " + n.json.asText());
        if (!n.json.isIntegralNumber()) throw fail(n.path, "must be a whole number, was " + describe(n.json));
        return n.json.asInt();
    }

    /** A direction: components in [-1, 1], not (almost) zero. */
    double[] direction(Node n) {
        double[] d = vector(n, Limits.NORMAL);
        double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (len < 1e-3) throw fail(n.path, "must not be (almost) zero, had length " + len);
        return d;
    }

    double[] vector(Node n, Limits.Range range) {
        if (!n.json.isArray() || n.json.size() != 3) throw fail(n.path, "must be [x, y, z], was " + describe(n.json));
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) v[i] = number(new Node(n.json.get(i), n.path + "[" + i + "]"), range);
        return v;
    }

    <E extends Enum<E>> E choice(Node n, Class<E> type) {
        String s = string(n);
        for (E e : type.getEnumConstants()) if (e.name().equalsIgnoreCase(s)) return e;
        String[] names = Arrays.stream(type.getEnumConstants()).map(e -> e.name().toLowerCase(Locale.ROOT)).toArray(String[]::new);
        throw fail(n.path, "must be one of " + String.join(", ", names) + ", was \"" + s + "\"");
    }

    static String describe(JsonNode j) {
        if (j.isTextual()) return "string \"" + j.asText() + "\"";
        if (j.isNumber()) return "number " + j.asText();
        if (j.isBoolean()) return "boolean " + j.asText();
        if (j.isArray()) return "an array of " + j.size();
        if (j.isObject()) return "an object";
        return j.getNodeType().toString().toLowerCase(Locale.ROOT);
    }
}
