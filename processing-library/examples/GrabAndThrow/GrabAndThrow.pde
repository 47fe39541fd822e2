// A free cloth lying on a ball above a floor (data/throw.json). Grab it with the mouse, swing it and let
// go: it flies with the speed you gave it and lands on the floor. r puts it back.
import xpbdcloth.library.*;

ClothView cloth;

void setup() {
  size(900, 650, P3D);
  cloth = new ClothView(this, "throw.json");  // looked up in this sketch's data folder
  cloth.pixelsPerMetre(220);
}

void draw() {
  background(34, 36, 42);
  lights();
  translate(width / 2, height * 0.85);
  rotateX(-0.35);
  cloth.draw();  // the floor is the preset's plane collider: ClothView draws colliders too
  if (cloth.grabbed() >= 0) {
    fill(255);
    text("holding particle " + cloth.grabbed(), 20, -height * 0.8);
  }
}
