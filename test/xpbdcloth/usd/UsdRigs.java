package xpbdcloth.usd;

import xpbdcloth.scene.Preset;
import xpbdcloth.scene.PresetLoader;

/** A scene with one of every collider the recorder writes (a spinning sphere on a circle, a turning box, a swinging capsule, a floor) under a fabric. */
final class UsdRigs {
    private UsdRigs() {}

    static Preset everyCollider() {
        return PresetLoader.parse("every-collider.json", 
                "{\n" +
                "  \"name\": \"every-collider\",\n" +
                "  \"cloth\": { \"columns\": 14, \"rows\": 10, \"width\": 0.7, \"height\": 0.5, \"plane\": \"horizontal\", \"origin\": [0, 1.2, 0], \"pins\": [] },\n" +
                "  \"fabric\": { \"catalogue\": \"denim\", \"warp\": [1, 0, 0], \"tethers\": false },\n" +
                "  \"solver\": { \"mode\": \"XPBD\", \"iterations\": 4, \"substeps\": 5, \"dt\": 0.02, \"mullerCorrection\": true, \"gravity\": [0, -9.81, 0], \"damping\": 0.5 },\n" +
                "  \"spheres\": [\n" +
                "    { \"radius\": 0.15, \"margin\": 0.01, \"staticFriction\": 0.5, \"kineticFriction\": 0.4, \"angularVelocity\": [0, 3, 1],\n" +
                "      \"path\": { \"type\": \"circle\", \"centre\": [0, 0.8, 0], \"radius\": 0.2, \"angularSpeed\": 2 } }\n" +
                "  ],\n" +
                "  \"colliders\": [\n" +
                "    { \"type\": \"box\", \"halfExtents\": [0.1, 0.05, 0.2], \"rotation\": [10, 20, 30], \"angularVelocity\": [0, 1.5, 0], \"margin\": 0.01,\n" +
                "      \"staticFriction\": 0.5, \"kineticFriction\": 0.4, \"path\": { \"type\": \"linear\", \"start\": [0.5, 0.6, 0], \"velocity\": [0, 0.1, 0.2] } },\n" +
                "    { \"type\": \"capsule\", \"axis\": [1, 1, 0], \"halfLength\": 0.2, \"radius\": 0.04, \"margin\": 0.01, \"staticFriction\": 1.0, \"kineticFriction\": 0.8,\n" +
                "      \"path\": { \"type\": \"oscillation\", \"centre\": [-0.4, 0.7, 0], \"amplitude\": [0.1, 0, 0.05], \"frequency\": 0.7 } },\n" +
                "    { \"type\": \"plane\", \"point\": [0, 0.1, 0], \"normal\": [0, 1, 0.2], \"margin\": 0.01, \"staticFriction\": 0.6, \"kineticFriction\": 0.45 }\n" +
                "  ]\n" +
                "}\n");
    }
}
