package xpbdcloth.engine;

/** Hears the end of every stage of a step (the probe of a diverged step); {@link #NONE} otherwise. */
interface StepObserver {
    StepObserver NONE = stage -> { };

    void after(Stage stage);
}
