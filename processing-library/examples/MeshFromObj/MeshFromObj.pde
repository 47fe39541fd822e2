// Any triangle (or polygon) mesh can be a cloth: data/tablecloth-on-ball.json names an OBJ file beside it
// (round-tablecloth.obj, a disc of 631 vertices made by xpbd-cloth's own generator) and drops it on a
// ball. Replace the OBJ with your own mesh, same units (metres), and name its pinned vertex group in the
// JSON if it has one ("pins": [{ "group": "name" }]).
import xpbdcloth.library.*;

ClothView cloth;

void setup() {
  size(900, 650, P3D);
  cloth = new ClothView(this, "tablecloth-on-ball.json");
  cloth.pixelsPerMetre(300);
}

void draw() {
  background(34, 36, 42);
  lights();
  translate(width / 2, height * 0.95);
  rotateX(-0.45);
  cloth.draw();
}
