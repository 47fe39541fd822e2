package xpbdcloth.tools;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The short versions of `gradle soak` and the fuzzer, as CI runs them. */
class RobustnessCommandsTest {
    /** corners and spinning-sphere for 3000 steps (60 s of simulated time) each stay within the soak's bounds. */
    @Test
    void shortSoak() {
        for (String scene : new String[] {"corners", "spinning-sphere"}) {
            Soak.Result r = Soak.run(scene, 3000);
            System.out.println(r);
            assertTrue(r.finite, scene + " finite");
            assertTrue(r.maxStrain < Soak.MAX_STRAIN, scene + " strain " + r.maxStrain);
            assertTrue(r.energyMax - r.energyStart < Soak.MAX_ENERGY_RISE, scene + " energy rise " + (r.energyMax - r.energyStart));
        }
    }

    /** 1000 seeded random cases (more with `gradle fuzz -Pcases=N`); a failure names its seed. */
    @Test
    void thousandFuzzCases() {
        StringBuilder failures = new StringBuilder();
        for (long seed = 1; seed <= 1000; seed++) {
            String why = Fuzz.runCase(seed);
            if (why != null) failures.append(why).append('\n');
        }
        assertEquals("", failures.toString());
    }
}
