// A cloth hanging from two corners, in twenty lines. Drag it with the mouse; space pauses, r resets,
// m switches between PBD and XPBD, i / I add or remove solver iterations.
import xpbdcloth.library.*;

ClothView cloth;

void setup() {
  size(800, 600, P3D);
  cloth = new ClothView(this, "hanging");
}

void draw() {
  background(34, 36, 42);
  lights();
  translate(width / 2, height * 0.9);  // the cloth's world origin: the floor, under its middle
  rotateY(0.4);
  cloth.draw();
}
