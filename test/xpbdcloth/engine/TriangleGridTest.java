package xpbdcloth.engine;

import org.junit.jupiter.api.Test;

import java.util.Arrays;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The grid's queries return exactly the boxes that overlap the query box, each once, whatever the cells' sizes. */
class TriangleGridTest {
    /**
     * Boxes from points to many cells wide (some past {@link TriangleGrid#MOST_CELLS}, into the list every query
     * reads), queries from points to wider than the whole table: each answer is, as a set, the brute-force
     * overlap test's, and no box is returned twice (a box listed in several cells, or in cells sharing a bucket).
     */
    @Test
    void aQueryFindsExactlyTheOverlappingBoxesEachOnce() {
        Random random = new Random(20261206);
        final int count = 400;
        double[] boxes = new double[6 * count];
        for (int t = 0; t < count; t++) {
            double size = t % 40 == 0 ? 3.0 : t % 5 == 0 ? 0.0 : 0.3 * random.nextDouble();
            for (int d = 0; d < 3; d++) {
                double lo = 4 * random.nextDouble() - 2;
                boxes[6 * t + d] = lo;
                boxes[6 * t + 3 + d] = lo + size * random.nextDouble();
            }
        }
        TriangleGrid grid = new TriangleGrid(0.1);
        grid.build(boxes, count);
        TriangleGrid.Query query = new TriangleGrid.Query();
        int answered = 0;
        for (int q = 0; q < 2000; q++) {
            double size = q % 100 == 0 ? 50.0 : q % 3 == 0 ? 0.0 : 0.5 * random.nextDouble();
            double[] lo = new double[3], hi = new double[3];
            for (int d = 0; d < 3; d++) { lo[d] = 4 * random.nextDouble() - 2 - (q % 100 == 0 ? 25 : 0); hi[d] = lo[d] + size * random.nextDouble(); }
            int found = grid.query(query, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
            int[] got = Arrays.copyOf(query.found(), found);
            Arrays.sort(got);
            int[] expected = new int[count];
            int n = 0;
            for (int t = 0; t < count; t++) {
                boolean overlaps = true;
                for (int d = 0; d < 3; d++) overlaps &= boxes[6 * t + d] <= hi[d] && lo[d] <= boxes[6 * t + 3 + d];
                if (overlaps) expected[n++] = t;
            }
            assertArrayEquals(Arrays.copyOf(expected, n), got, "query " + q);
            answered += n;
        }
        assertTrue(answered > 1000, "the queries found boxes (" + answered + ")");
    }
}
