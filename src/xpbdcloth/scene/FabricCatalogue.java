package xpbdcloth.scene;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import xpbdcloth.fabric.Fabric;

/**
 * The measured fabrics shipped in {@code data/fabrics.json} (in the jar beside the built-in presets),
 * read once: what the sketch's fabric key cycles through and what a preset's
 * {@code "fabric": {"catalogue": NAME}} names.
 */
public final class FabricCatalogue {
    public static final String FILE = "fabrics.json";
    private static List<Fabric> fabrics;

    private FabricCatalogue() {}

    /** All fabrics, in the file's order. */
    public static synchronized List<Fabric> all() {
        if (fabrics == null) {
            try (InputStream in = FabricCatalogue.class.getResourceAsStream("/presets/" + FILE)) {
                if (in == null) throw new PresetException(FILE, "(file)", "is missing from the built-in presets");
                fabrics = List.copyOf(PresetLoader.parseCatalogue(FILE, new String(in.readAllBytes(), StandardCharsets.UTF_8)));
            } catch (IOException e) {
                throw new PresetException(FILE, "(file)", "cannot be read: " + e.getMessage());
            }
        }
        return fabrics;
    }

    /** The fabric of that name, or null. */
    public static Fabric named(String name) {
        for (Fabric f : all()) if (f.name.equals(name)) return f;
        return null;
    }

    public static List<String> names() {
        List<String> out = new ArrayList<>();
        for (Fabric f : all()) out.add(f.name);
        return out;
    }

    /** The fabric after {@code current} in the catalogue (the first if current is not in it), wrapping. */
    public static Fabric after(Fabric current) {
        List<Fabric> all = all();
        int k = all.indexOf(current);
        return all.get((k + 1) % all.size());
    }
}
