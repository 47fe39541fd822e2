package xpbdcloth.experiments;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** A CSV table whose header names each column with its unit, e.g. {@code stretch_m}. */
final class Table {
    final String name;
    final String[] columns;
    final List<Object[]> rows = new ArrayList<>();

    Table(String name, String... columns) {
        this.name = name;
        this.columns = columns;
    }

    void add(Object... row) {
        if (row.length != columns.length) throw new IllegalArgumentException("row must have " + columns.length + " values, was " + row.length);
        rows.add(row);
    }

    Path write(Path folder) throws IOException {
        StringBuilder sb = new StringBuilder(String.join(",", columns)).append('\n');
        for (Object[] r : rows) {
            for (int i = 0; i < r.length; i++) {
                if (i > 0) sb.append(',');
                Object v = r[i];
                if (v instanceof Double) sb.append(String.format(Locale.ROOT, "%.9g", (Double) v));
                else sb.append(v);
            }
            sb.append('\n');
        }
        Path file = folder.resolve(name + ".csv");
        Files.writeString(file, sb.toString());
        return file;
    }
}
