/**
 * The Processing library's face (imported by a sketch as {@code import xpbdcloth.library.*;}): a
 * {@link xpbdcloth.library.ClothView} puts a simulated cloth into any P3D sketch, steps it, draws it in
 * the sketch's own coordinates and lets the mouse grab it. It is built from the sketch package's parts
 * (state, key table, renderer); nothing below it imports it.
 */
package xpbdcloth.library;
