// The same cloth twice: PBD on the left, XPBD on the right. Press i / I to change the number of solver
// iterations and t to change the timestep. The PBD cloth's stretch follows the iteration count; the XPBD
// cloth's stays where its compliance puts it (that is the point of XPBD).
import xpbdcloth.library.*;
import xpbdcloth.engine.*;

ClothView cloth;

void setup() {
  size(1000, 600, P3D);
  cloth = new ClothView(this, "hanging").sideBySide(true);
  cloth.pixelsPerMetre(260);
}

void draw() {
  background(34, 36, 42);
  pushMatrix();
  lights();
  translate(width / 2, height * 0.95);
  cloth.draw();
  popMatrix();
  noLights();
  fill(235);
  textSize(16);
  java.util.List<Simulation> sims = cloth.simulations();
  text("iterations " + cloth.iterations() + "  (i / I)    dt 1/" + round(1 / (float) cloth.dt()) + " s  (t)", 20, 30);
  for (int i = 0; i < sims.size(); i++) {
    Simulation sim = sims.get(i);
    float strain = 100 * (float) Metrics.maxStrain(sim, ConstraintFamily.STRUCTURAL);
    text((i == 0 ? "PBD" : "XPBD") + "  max stretch " + nf(strain, 1, 2) + " %", 20 + i * width / 2, height - 20);
  }
}
