/**
 * Scenes and their preset files.
 * <ul>
 *   <li>{@link xpbdcloth.scene.Preset}: a validated, immutable description of a scene.</li>
 *   <li>{@link xpbdcloth.scene.PresetLoader}: strict JSON reading with file/field/problem errors.</li>
 *   <li>{@link xpbdcloth.scene.PresetException}: the error a broken preset gives.</li>
 *   <li>{@link xpbdcloth.scene.Scene}: a running scene built from a preset.</li>
 *   <li>PinScript: pinned particles moved along eased paths (the corners scene).</li>
 * </ul>
 */
package xpbdcloth.scene;
