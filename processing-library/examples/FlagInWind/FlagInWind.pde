// A flag with a hole, held along its hoist, in a gusting wind. w turns the wind on and off, d turns it by
// 45°, e / E make it stronger or weaker; x shows the strain as colours.
import xpbdcloth.library.*;

ClothView cloth;

void setup() {
  size(900, 600, P3D);
  cloth = new ClothView(this, "flag");
  cloth.pixelsPerMetre(320);
}

void draw() {
  background(205, 208, 212);
  float s = cloth.pixelsPerMetre();
  pushMatrix();
  lights();
  translate(width * 0.4, height * 0.2 + 2.0 * s);  // the scene's origin: the flag's top is 2 m above it
  rotateY(-0.5);
  cloth.draw();
  // The pole along the hoist (x = -0.75 m), from the ground to a little above the flag.
  translate(-0.75 * s, -1.05 * s, 0);
  noStroke();
  fill(110);
  box(0.025 * s, 2.1 * s, 0.025 * s);
  popMatrix();
  noLights();
  fill(20);
  textSize(15);
  text("wind " + nf((float) cloth.windSpeed(), 1, 1) + " m/s " + (cloth.windOn() ? "on" : "off") + "   (w, d, e / E)", 20, 30);
}
