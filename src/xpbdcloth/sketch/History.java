package xpbdcloth.sketch;

/** The last few seconds of a quantity, in a ring buffer made once, for the HUD's live plots. */
final class History {
    private final float[] values;
    private int next, size;

    History(int capacity) { values = new float[capacity]; }

    void add(double v) {
        values[next] = (float) v;
        next = (next + 1) % values.length;
        if (size < values.length) size++;
    }

    void clear() { next = size = 0; }

    int size() { return size; }

    int capacity() { return values.length; }

    /** The i-th oldest value, 0 ≤ i &lt; size. */
    float get(int i) { return values[(next - size + i + values.length) % values.length]; }

    float max() {
        float m = 0;
        for (int i = 0; i < size; i++) m = Math.max(m, get(i));
        return m;
    }
}
