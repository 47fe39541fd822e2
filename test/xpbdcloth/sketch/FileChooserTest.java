package xpbdcloth.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The sketch's chooser opens where the sketch writes and shows the kind of file the key wants, not GTK's recent list. */
class FileChooserTest {
    @Test
    void opensInTheSketchsFolderShowingTheFilesTheKeyTakes(@TempDir Path dir) throws Exception {
        File preset = Files.writeString(dir.resolve("scene.json"), "{}").toFile();
        File mesh = Files.writeString(dir.resolve("rest.obj"), "v 0 0 0").toFile();
        File folder = Files.createDirectory(dir.resolve("more")).toFile();
        JFileChooser json = FileChooser.chooser("Load a scene preset (JSON)", dir.toFile(), "Scene presets", "json");
        assertEquals(dir.toFile().getCanonicalFile(), json.getCurrentDirectory().getCanonicalFile());
        assertTrue(json.getFileFilter().accept(preset), "a preset is shown");
        assertFalse(json.getFileFilter().accept(mesh), "an OBJ is not, for a preset");
        assertTrue(json.getFileFilter().accept(folder), "folders are, to go through");
        JFileChooser obj = FileChooser.chooser("Fit", dir.toFile(), "Wavefront OBJ", "obj");
        assertTrue(obj.getFileFilter().accept(mesh) && !obj.getFileFilter().accept(preset));
        assertEquals("Wavefront OBJ (*.obj)", obj.getFileFilter().getDescription());
    }
}
