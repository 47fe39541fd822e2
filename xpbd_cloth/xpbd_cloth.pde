// xpbd-cloth in the Processing IDE. The sketch lives in the project's jar: run `gradle sketchJar`
// once (it copies the jar and its libraries into this folder's code/), then press Run.
// Everything else, keys, camera, HUD, is the same as `gradle run`.
import xpbdcloth.sketch.*;

ClothApp cloth;

void settings() {
  size(1280, 800, P3D);
  smooth(4);
}

void setup() {
  surface.setResizable(true);
  cloth = new ClothApp(this);  // registers its own draw, key and mouse handlers
}

void draw() {
  // ClothApp draws through registerMethod("draw").
}
