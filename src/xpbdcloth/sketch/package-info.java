/**
 * The Processing sketch (imports Processing; the engine does not).
 * <ul>
 *   <li>{@link xpbdcloth.sketch.ClothApp}: the sketch, hooked into any PApplet by registerMethod.</li>
 *   <li>{@link xpbdcloth.sketch.Launcher}: a PApplet that opens it outside the Processing IDE.</li>
 *   <li>{@link xpbdcloth.sketch.SketchState}: what the controls change, testable without a window.</li>
 *   <li>{@link xpbdcloth.sketch.KeyBindings}: the one key table, read by the handler and the help.</li>
 *   <li>{@link xpbdcloth.sketch.OrbitCamera}: PeasyCam-style orbit camera and the HUD begin/end pair.</li>
 *   <li>{@link xpbdcloth.sketch.Quaternion}: camera orientation.</li>
 *   <li>ClothRenderer, Hud, History: drawing the cloth, the heads-up display and its live plots.</li>
 * </ul>
 */
package xpbdcloth.sketch;
