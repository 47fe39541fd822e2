package xpbdcloth.sketch;

import java.io.File;
import java.util.function.Consumer;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The sketch's file chooser: Swing's own, opened in the folder the sketch writes to, showing first the kind of
 * file the key wants. Processing's {@code selectInput} opens the desktop's native dialog, which on Linux is
 * GTK's: it starts on an empty "Recently Used" list with no filter, and prints GTK warnings to the terminal
 * where the user's home has no {@code .local/share}.
 */
final class FileChooser {
    private FileChooser() {}

    /** The chooser {@link #open} shows (apart so that a test can look at it without a dialog). */
    static JFileChooser chooser(String title, File folder, String kind, String extension) {
        JFileChooser c = new JFileChooser(folder);
        c.setDialogTitle(title);
        c.setFileFilter(new FileNameExtensionFilter(kind + " (*." + extension + ")", extension));
        c.setPreferredSize(new java.awt.Dimension(760, 480)); // Swing's default shows three names a column
        return c;
    }

    /**
     * Opens the chooser on Swing's thread and hands the file chosen, or null if none, to {@code then} there,
     * whatever happens in between (the sketch ignores its keys until it is called).
     */
    static void open(String title, File folder, String kind, String extension, Consumer<File> then) {
        SwingUtilities.invokeLater(() -> {
            File chosen = null;
            try {
                JFileChooser c = chooser(title, folder, kind, extension);
                if (c.showOpenDialog(null) == JFileChooser.APPROVE_OPTION) chosen = c.getSelectedFile();
            } finally {
                then.accept(chosen);
            }
        });
    }
}
