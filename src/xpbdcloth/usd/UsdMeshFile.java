package xpbdcloth.usd;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

/**
 * A triangle mesh whose points change per frame, as a USD text stage of its own: one {@code Mesh} prim
 * under {@code /World}, its triangles once and its points time-sampled, time code k at k/fps seconds,
 * metres, y up, coordinates to 10 µm. How the project ships an animated body (the mannequin turning) that
 * {@link xpbdcloth.mesh.BodyMesh} reads back.
 */
public final class UsdMeshFile {
    private UsdMeshFile() {}

    /** A coordinate rounded to 10 µm: a shipped body's shape to far below any cloth's thickness, in fewer digits. */
    static double tenMicrometres(double v) { return Math.rint(v * 1e5) / 1e5; }

    public static void write(Writer w, String primName, int[] triangles, double[][] frames, double fps, String doc) throws IOException {
        if (frames.length == 0) throw new IllegalArgumentException("frames must hold at least one frame, was none");
        if (!(fps > 0)) throw new IllegalArgumentException("fps must be > 0, was " + fps);
        StringBuilder b = new StringBuilder();
        b.append("#usda 1.0\n(\n    defaultPrim = \"World\"\n    doc = ").append(UsdaText.quoted(doc)).append('\n');
        b.append("    endTimeCode = ").append(frames.length - 1).append("\n    framesPerSecond = ");
        UsdaText.appendDouble(b, fps).append("\n    metersPerUnit = 1\n    startTimeCode = 0\n    timeCodesPerSecond = ");
        UsdaText.appendDouble(b, fps).append("\n    upAxis = \"Y\"\n)\n\ndef Xform \"World\"\n{\n    def Mesh ").append(UsdaText.quoted(UsdaText.identifier(primName))).append("\n    {\n");
        b.append("        int[] faceVertexCounts = [");
        for (int t = 0; t < triangles.length / 3; t++) b.append(t == 0 ? "" : ", ").append(3);
        b.append("]\n        int[] faceVertexIndices = [");
        for (int i = 0; i < triangles.length; i++) b.append(i == 0 ? "" : ", ").append(triangles[i]);
        b.append("]\n        point3f[] points.timeSamples = {\n");
        w.write(b.toString());
        for (int f = 0; f < frames.length; f++) {
            b.setLength(0);
            b.append("            ").append(f).append(": [");
            double[] x = frames[f];
            for (int i = 0; i < x.length; i += 3) {
                b.append(i == 0 ? "(" : ", (");
                UsdaText.appendFloat(b, tenMicrometres(x[i])).append(", ");
                UsdaText.appendFloat(b, tenMicrometres(x[i + 1])).append(", ");
                UsdaText.appendFloat(b, tenMicrometres(x[i + 2])).append(')');
            }
            w.write(b.append("],\n").toString());
        }
        w.write(String.format(Locale.ROOT, "        }\n        uniform token subdivisionScheme = \"none\"\n    }\n}\n"));
    }
}
