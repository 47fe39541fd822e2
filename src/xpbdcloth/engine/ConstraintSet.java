package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * A simulation's constraints: the cloth's, block by block in Gauss–Seidel order, then the attachments
 * (grabs), which come and go while the cloth stays. Two counters say what changed since a solve stage was
 * chosen: {@link #clothVersion} when the cloth's constraints change (a colouring or a global system must be
 * remade), {@link #version} when anything does (grabbing too: only the order is remade).
 */
final class ConstraintSet {
    private final int particleCount;
    private final List<ConstraintBlock> cloth = new ArrayList<>();
    private final List<ConstraintBlock> clothView = Collections.unmodifiableList(cloth);
    /** The last block made here for constraints added one by one (the only cloth block that grows). */
    private ConstraintBlock openBlock;
    private final AttachmentBlock attachments = new AttachmentBlock(4);
    /** The views handed out by {@link #attach}, re-indexed when one is released. */
    private final List<AttachmentConstraint> grabs = new ArrayList<>();
    /** The cloth constraints in solve order, then the attachments: made when first asked for after a change. */
    private SweepOrder order;
    private Constraint[] views;
    private long clothVersion, version;

    ConstraintSet(int particleCount) {
        this.particleCount = particleCount;
        attachments.owner = this;
    }

    List<ConstraintBlock> cloth() { return clothView; }
    AttachmentBlock attachments() { return attachments; }
    long clothVersion() { return clothVersion; }
    long version() { return version; }

    /** The cloth constraints and then the attachments, in insertion order. */
    SweepOrder order() {
        if (order == null) {
            List<ConstraintBlock> all = new ArrayList<>(cloth);
            all.add(attachments);
            order = SweepOrder.asBuilt(all);
        }
        return order;
    }

    /** Views of the constraints in solve order (cloth, then attachments); do not modify. */
    Constraint[] views() {
        if (views == null) {
            List<Constraint> v = new ArrayList<>();
            for (ConstraintBlock b : cloth) for (int i = 0; i < b.count(); i++) v.add(b.view(i));
            v.addAll(grabs);
            views = v.toArray(new Constraint[0]);
        }
        return views;
    }

    int count() {
        int n = attachments.count();
        for (ConstraintBlock b : cloth) n += b.count();
        return n;
    }

    /** Adds constraints in order, taking their data into this set's blocks (each object stays its view); all are checked first. */
    void addAll(List<? extends Constraint> cs) {
        Set<Constraint> seen = new HashSet<>();
        for (Constraint c : cs) {
            if (c == null) throw new IllegalArgumentException("constraint must not be null, was null");
            for (int i : c.particles()) Check.index("constraint particle", i, particleCount);
            if (c.block.owner != null)
                throw new IllegalArgumentException("constraint must not be in a simulation already, was a " + c.family() + " constraint of " + (c.block.owner == this ? "this one" : "another"));
            if (!seen.add(c)) throw new IllegalArgumentException("constraint must be added once, was listed twice (" + c.family() + ")");
        }
        for (Constraint c : cs) {
            ConstraintBlock last = cloth.isEmpty() ? null : cloth.get(cloth.size() - 1);
            if (last == null || last != openBlock || last.getClass() != c.block.getClass() || last.family() != c.family()) {
                openBlock = c.block.emptyLike(16);
                openBlock.owner = this;
                cloth.add(openBlock);
            }
            int j = openBlock.appendCopy(c.block, c.index);
            c.block = openBlock;
            c.index = j;
        }
        clothChanged();
    }

    /** Adds whole blocks (a cloth's) after the constraints already here, taking them over, or copies of them if another set has them. */
    void addBlocks(List<ConstraintBlock> blocks) {
        for (ConstraintBlock b : blocks) {
            if (b == null) throw new IllegalArgumentException("block must not be null, was null");
            for (int i = 0; i < b.count(); i++)
                for (int k = 0; k < b.arity(); k++) Check.index("constraint particle", b.particle(i, k), particleCount);
        }
        for (ConstraintBlock b : blocks) {
            ConstraintBlock mine = b;
            if (b.owner != null) {
                mine = b.emptyLike(b.count());
                for (int i = 0; i < b.count(); i++) mine.appendCopy(b, i);
            }
            mine.owner = this;
            cloth.add(mine);
        }
        openBlock = null;
        clothChanged();
    }

    AttachmentConstraint attach(int i, double x, double y, double z) {
        Check.index("particle", i, particleCount);
        AttachmentConstraint a = attachments.view(attachments.add(i, x, y, z));
        grabs.add(a);
        changed();
        return a;
    }

    /** Lets go of an attachment made by {@link #attach}; the object keeps its particle and target in a block of its own. */
    void release(AttachmentConstraint a) {
        int k = grabs.indexOf(a);
        if (k < 0) return;
        AttachmentBlock own = new AttachmentBlock(1);
        own.appendCopy(attachments, a.index);
        attachments.remove(a.index);
        grabs.remove(k);
        for (int j = k; j < grabs.size(); j++) grabs.get(j).index--;
        a.block = own;
        a.index = 0;
        changed();
    }

    void setStiffness(ConstraintFamily family, double k) {
        Check.inRange("stiffness", k, 0, 1);
        for (ConstraintBlock b : cloth) if (b.family() == family) b.setStiffness(k);
    }

    void setMaterial(ConstraintFamily family, Material m) {
        for (ConstraintBlock b : cloth) if (b.family() == family) b.setMaterial(m);
    }

    void setCompliance(ConstraintFamily family, double alpha) {
        Check.nonNegative("compliance", alpha);
        Check.inRange("compliance", alpha, 0, EngineRange.MAX_COMPLIANCE);
        for (ConstraintBlock b : cloth) if (b.family() == family) b.setCompliance(alpha);
    }

    /** Marks the attached particles. */
    void markAttached(boolean[] held) {
        for (int i = 0; i < attachments.count(); i++) held[attachments.particle(i, 0)] = true;
    }

    private void clothChanged() {
        clothVersion++;
        changed();
    }

    private void changed() {
        version++;
        order = null;
        views = null;
    }
}
