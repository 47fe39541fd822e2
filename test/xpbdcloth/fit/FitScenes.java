package xpbdcloth.fit;

/** Scenes the fit tests share, as preset text. */
public final class FitScenes {
    private FitScenes() {}

    public static final String DENIM_DRAPE = "{\"name\": \"denim-drape\", \"description\": \"drape as denim\","
            + " \"cloth\": {\"columns\": 16, \"rows\": 16, \"width\": 0.25, \"height\": 0.25, \"plane\": \"horizontal\", \"origin\": [0, 1.2, 0],"
            + " \"pins\": [\"top-left\", \"top-right\", \"bottom-left\"]},"
            + " \"fabric\": {\"catalogue\": \"denim\", \"warp\": [1, 0, 0]},"
            + " \"solver\": {\"mode\": \"XPBD\", \"iterations\": 10, \"substeps\": 5, \"dt\": 0.02, \"damping\": 0.5}}";
}
