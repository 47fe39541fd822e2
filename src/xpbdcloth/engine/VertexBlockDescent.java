package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The solve stage of {@link SolverType#VERTEX_BLOCK_DESCENT}: the same implicit Euler step XPBD solves,
 * in positions rather than multipliers. Each iteration visits the free particles one at a time and moves
 * each to the minimum of the step's energy with the others held (a 3 × 3 Newton step), Chen, Lan, Wu, Cao,
 * Yuksel, Liu, Macklin, Kavan 2024, "Vertex Block Descent":
 * <pre>
 *   G(x) = Σᵢ mᵢ|xᵢ − yᵢ|² / (2h²) + Σⱼ Cⱼ(x)² / (2αⱼ),     y = x_prev + h v + h² (g + w f)
 *   per particle i:  fᵢ = −mᵢ(xᵢ − yᵢ)/h² − Σⱼ (Cⱼ/αⱼ) ∇ᵢCⱼ,   Hᵢ = mᵢ/h² I + Σⱼ (∇ᵢCⱼ∇ᵢCⱼᵀ + [Cⱼ∇²ᵢᵢCⱼ]₊) / αⱼ,   xᵢ += Hᵢ⁻¹ fᵢ
 * </pre>
 * ([·]₊: the second-derivative term where it stiffens, so Hᵢ stays positive definite). The compliances
 * are XPBD's. What has no compliance enters as a stiff penalty (a tether's stretch, two layers of the
 * cloth closer than its thickness, with friction as a lagged dissipative force), is met right after the
 * particle's step (a contact with a solid, which keeps its continuous tests) or holds the particle throughout
 * (a hard attachment: the particle stays on its hand's target, as on a moving pin, and the hand takes the
 * force); a hard constraint of another kind (α = 0 has no energy) is projected as in XPBD after each iteration.
 *
 * <p>Why: XPBD resets λ every substep, so a Gauss–Seidel sweep rebuilds every force from nothing, and
 * the few sweeps a step can afford carry a pin's hold only a few edges into the cloth: its rest sags and
 * stretches more the finer the mesh. Here the forces are functions of the positions, and the iteration
 * starts from x_prev + h v (not y): at rest that is the rest itself, where every fᵢ is already 0, so a
 * cloth at rest is a fixed point whatever the sweep count, and the rest the scene settles to is the
 * energy's minimum, the converged cloth. What few sweeps cost is lag while the cloth moves, not a
 * softer rest.
 *
 * <p>A few sweeps leave the step short of its minimum, and on a cloth far stiffer than its inertia what they
 * leave can come back as speed: each substep ends with the energy checked against implicit Euler's bound
 * and the speed scaled down where the sweeps exceeded it, or the substep solved again by Gauss–Seidel where
 * its strain alone did ({@link #withoutEnergyGain}).
 *
 * <p>Particles of one colour share no energy term, so a colour's particles can be solved in any order or
 * on any number of threads with the same result. Membrane triangles, quadratic hinges, springs and tethers
 * have closed forms here ({@link #takes}).
 */
final class VertexBlockDescent implements SolveStage, Team.Job {
    private final Particles particles;
    private final SolverContext ctx;
    /** What is projected after each iteration: hard and inequality blocks, attachments (XPBD), then contacts. */
    private final SweepOrder rest;
    /** Projected after {@link #rest}: one row over a whole surface each, no per-vertex energy to descend. */
    private final EnclosedGases gases;
    private final ContactSet contacts;
    private final SweepListener listener;
    /** The threads a substep's iterations run on, or null for this one (and for a listener to single iterations). */
    private final Team team;
    private int iterations;
    private double inverseH2;
    private final int n;
    /** The inertial target y of the substep. */
    private final double[] target;
    /** The substep's start without motion: the free particles where the substep began, the pinned where they are now, the held at their targets. */
    private final double[] stillStart;
    /**
     * Per free particle, the hard attachment holding it this substep (a grab), or −1. A held particle is the
     * hand's: it stays on the target through the iterations, as a moving pin would, and the energy bound counts
     * it as it counts a pin's.
     */
    private final int[] heldBy;
    /** The held particles of this substep, the first {@link #heldCount}: what {@link #heldBy} marks, so a substep walks the hands, not the cloth. */
    private final int[] held;
    private int heldCount;
    /** Per held particle, xyz: the force its hand exerts to keep it on the target, from its last iteration. */
    private final double[] handForce;

    // Membrane triangles: particles, D⁻¹ (P, Q, R, S), K = Σ_r r rᵀ/α_r (K00, K01, K11, K22) and their source rows.
    private final int[] triParticle;
    private final double[] triRest, triK;
    private final MembraneBlock[] triBlock;
    private final int[] triRow;
    // Quadratic hinges and bending patches' rows: particles, coefficients, 1/α per component, and their source.
    /** Slots per hinge in the arrays below: the most particles any of them takes (4 for hinges, up to 12 for patches). */
    private final int hingeSlots;
    private final int[] hingeParticle;
    private final double[] hingeCoefficient;
    private final QuadraticBendBlock[] hingeBlock;
    private final int[] hingeUnit;
    // Springs: particles, rest length, 1/α, and their source.
    private final int[] springParticle;
    private final double[] springRest, springStiffness;
    private final DistanceBlock[] springBlock;
    private final int[] springRow;
    // Tethers (the anchor is pinned): anchor, free particle, longest distance.
    private final int[] tetherAnchor, tetherStart, tetherOf;
    private final double[] tetherDistance;
    /** The attachments (grabs): where each particle's are listed, to be met after its step. */
    private final AttachmentBlock attachments;
    /** The cloth's blocks, and Gauss–Seidel's sweeps over them: what redoes a substep whose sweeps climbed ({@link #redoByGaussSeidel}). */
    private final List<ConstraintBlock> body;
    private final SequentialSweeps gaussSeidel;
    /** The substep being solved, for the listener of a redone one. */
    private int substep;
    private final int[] attachedStart, attachedOf;
    /** The families taken as energies, for the report of a step that diverged. */
    private final ConstraintFamily firstFamily;
    // Per particle: the incidences of each kind (CSR): element·arity + slot.
    private final int[] triStart, triOf, hingeStart, hingeOf, springStart, springOf;
    /** Per membrane incidence, the particle's (a, b): ∂f_u/∂x = a, ∂f_v/∂x = b (so the loop has no branch on the slot). */
    private final double[] triA, triB;
    /**
     * The hinges' energy is quadratic with constant coefficients, ½ Σ_h k_h |Σ c_k x_k|², so its force on a
     * particle is linear in the positions: −Σ_u B_vu x_u with B = Σ_h k_h c_h c_hᵀ, the same on each axis (a
     * hinge's three rows share their compliance, {@link ConstraintBlock#rowsShareMaterial}). B's row of v lists
     * the particles v shares a hinge with (itself included): bendStart[v] .. bendStart[v + 1] into bendColumn
     * and bendValue. Summed once per material change, it costs a particle a few dozen products where
     * evaluating its dozen hinges cost some three hundred. One value an entry, not one per axis: at 128² the
     * matrix no longer fits the cache three times over, and the sweep waits on memory.
     */
    private final int[] bendStart, bendColumn, bendEntry, bendDiagonal;
    private final double[] bendValue;
    /** Colours of the particles: colour c is order[colourStart[c] .. colourStart[c + 1]). */
    final int[] order, colourStart;
    private int colourCount;
    /** Scratch of the colouring: which colours the particle being coloured has among its neighbours. */
    private final int[] colourMark;
    /** The self-collision list the colouring took in (its build count), −1 for none. */
    private long colouredForBuild = -1;
    /** This substep's contacts by particle (CSR), rebuilt after each collide stage. */
    private final int[] contactStart;
    private int[] contactOf = new int[16];
    /**
     * The most a particle may move in one step of its own: half its shortest edge at rest (to the nearest
     * particle it shares a term with). A Newton step is exact for the quadratic terms, but the angle of a
     * shear constraint is far from linear and its step can fling the particle (as {@link ShearBlock}'s
     * projection limits its own).
     */
    private final double[] stepLimit;
    /** Each particle's colour. */
    private final int[] colourOf;
    /**
     * A pair contact's stiffness is this over h²(w_a + w_b): the pair's effective mass over h², times this,
     * so the contact outweighs inertia and its overlap at rest is a fraction of a micrometre (g h²/100). Not
     * much stiffer: a particle's own step then takes the whole of a pair's correction and its partner none, and
     * two layers sliding without friction gained energy (1000 on denim-fold blew up; 300 did at 15 × 1
     * sweeps). At 100 the fold settles (kinetic energy below 1e-8 J) at 10 × 2, 10 × 1 and 15 × 1.
     */
    static final double CONTACT_STIFFNESS = 100;
    /** A particle's own step is at most this fraction of its shortest edge at rest. */
    static final double MAX_STEP = 0.5;
    /** A tether's penalty stiffness is this times the particle's m/h² (its anchor is pinned: nothing to share). */
    static final double HARD_STIFFNESS = 1e3;
    /** Below this slip speed (m/s) friction is smoothed stick, above it kinetic (IPC's ε_v). */
    static final double SLIP = 1e-3;

    /**
     * Whether this stage takes block b as an energy: a compliant membrane, quadratic bend or spring as XPBD's
     * ½C²/α, a tether as a stiff penalty on its stretch. Any other is projected as in XPBD after each
     * iteration: a hard constraint (α = 0 has no energy), and the angle constraints (shear, triangle bend,
     * dihedral), whose Gauss–Newton step from a particle's view overshoots (a stiff shear grid at one sweep
     * a substep blew up): those are far from linear where the others are quadratic or nearly.
     */
    static boolean takes(ConstraintBlock b) {
        if (b instanceof TetherBlock) return true;
        if (!(b instanceof MembraneBlock || b instanceof QuadraticBendBlock || b instanceof DistanceBlock)) return false;
        for (int i = 0; i < b.count(); i++) if (!(b.compliance(i) > 0)) return false;
        return true;
    }

    VertexBlockDescent(List<ConstraintBlock> body, AttachmentBlock attachments, Particles particles, SolverContext ctx,
                       EnclosedGases gases, ContactSet contacts, SweepListener listener, Team team, SequentialSweeps gaussSeidel) {
        this.particles = particles;
        this.body = body;
        this.gaussSeidel = gaussSeidel;
        this.ctx = ctx;
        this.gases = gases;
        this.contacts = contacts;
        this.listener = listener;
        this.team = team;
        n = particles.count();
        target = new double[3 * n];
        stillStart = new double[3 * n];
        keptPositions = new double[3 * n];
        heldBy = new int[n];
        Arrays.fill(heldBy, -1);
        held = new int[n];
        handForce = new double[3 * n];
        contactStart = new int[n + 1];
        List<ConstraintBlock> projected = new ArrayList<>();
        List<MembraneBlock> membranes = new ArrayList<>();
        List<QuadraticBendBlock> hinges = new ArrayList<>();
        List<DistanceBlock> springs = new ArrayList<>();
        List<TetherBlock> tethers = new ArrayList<>();
        for (ConstraintBlock b : body) {
            if (b.count() == 0) continue;
            if (!takes(b)) projected.add(b);
            else if (b instanceof MembraneBlock) membranes.add((MembraneBlock) b);
            else if (b instanceof QuadraticBendBlock) hinges.add((QuadraticBendBlock) b);
            else if (b instanceof DistanceBlock) springs.add((DistanceBlock) b);
            else tethers.add((TetherBlock) b);
        }
        rest = SweepOrder.asBuilt(projected);
        projectedBlocks = projected.toArray(new ConstraintBlock[0]);
        this.attachments = attachments;
        firstFamily = !membranes.isEmpty() ? ConstraintFamily.MEMBRANE : !hinges.isEmpty() ? ConstraintFamily.DIHEDRAL
                : !springs.isEmpty() ? springs.get(0).family() : ConstraintFamily.TETHER;

        int triangles = 0, hingeCount = 0, springCount = 0, slots = 4;
        for (QuadraticBendBlock q : hinges) slots = Math.max(slots, q.arity());
        this.hingeSlots = slots;
        for (MembraneBlock m : membranes) triangles += m.units();
        for (QuadraticBendBlock q : hinges) hingeCount += q.units();
        for (DistanceBlock d : springs) springCount += d.count();
        triParticle = new int[3 * triangles]; triRest = new double[4 * triangles]; triK = new double[4 * triangles];
        triBlock = new MembraneBlock[triangles]; triRow = new int[triangles];
        int t = 0;
        for (MembraneBlock m : membranes)
            for (int u = 0; u < m.units(); u++, t++) {
                int i = 3 * u;
                for (int k = 0; k < 3; k++) triParticle[3 * t + k] = m.particle(i, k);
                System.arraycopy(m.restInverse, 4 * i, triRest, 4 * t, 4);
                triBlock[t] = m;
                triRow[t] = i;
            }
        // Every hinge or patch row in hingeSlots slots, those past its own arity empty (−1).
        hingeParticle = new int[hingeSlots * hingeCount]; hingeCoefficient = new double[hingeSlots * hingeCount];
        Arrays.fill(hingeParticle, -1);
        hingeBlock = new QuadraticBendBlock[hingeCount]; hingeUnit = new int[hingeCount];
        int h = 0;
        for (QuadraticBendBlock q : hinges)
            for (int u = 0; u < q.units(); u++, h++) {
                for (int k = 0, arity = q.arity(); k < arity; k++) {
                    double c = q.coefficient[arity * u + k];
                    if (c == 0) continue;
                    hingeParticle[hingeSlots * h + k] = q.particle(3 * u, k);
                    hingeCoefficient[hingeSlots * h + k] = c;
                }
                hingeBlock[h] = q;
                hingeUnit[h] = u;
            }
        springParticle = new int[2 * springCount]; springRest = new double[springCount]; springStiffness = new double[springCount];
        springBlock = new DistanceBlock[springCount]; springRow = new int[springCount];
        int s = 0;
        for (DistanceBlock d : springs)
            for (int i = 0; i < d.count(); i++, s++) {
                springParticle[2 * s] = d.a(i);
                springParticle[2 * s + 1] = d.b(i);
                springRest[s] = d.restLength(i);
                springBlock[s] = d;
                springRow[s] = i;
            }
        int tetherCount = 0;
        for (TetherBlock tb : tethers) tetherCount += tb.count();
        tetherAnchor = new int[tetherCount];
        tetherDistance = new double[tetherCount];
        int[] tetherFree = new int[tetherCount];
        int tt = 0;
        for (TetherBlock tb : tethers)
            for (int i = 0; i < tb.count(); i++, tt++) {
                tetherAnchor[tt] = tb.particle(i, 0);
                tetherFree[tt] = tb.particle(i, 1);
                tetherDistance[tt] = tb.restDistance(i);
            }
        tetherStart = new int[n + 1];
        tetherOf = incidences(tetherFree, 1, tetherStart);
        int[] attached = new int[attachments.count()];
        for (int i = 0; i < attached.length; i++) attached[i] = attachments.particle(i, 0);
        attachedStart = new int[n + 1];
        attachedOf = incidences(attached, 1, attachedStart);
        triStart = new int[n + 1]; hingeStart = new int[n + 1]; springStart = new int[n + 1];
        triOf = incidences(triParticle, 3, triStart);
        hingeOf = incidences(hingeParticle, hingeSlots, hingeStart);
        springOf = incidences(springParticle, 2, springStart);
        List<ConstraintBlock> sources = new ArrayList<>(membranes);
        sources.addAll(hinges);
        sources.addAll(springs);
        stiffnessSources = sources.toArray(new ConstraintBlock[0]);
        triA = new double[triOf.length];
        triB = new double[triOf.length];
        for (int e = 0; e < triOf.length; e++) {
            int tri = triOf[e] / 3, slot = triOf[e] % 3;
            double P = triRest[4 * tri], Q = triRest[4 * tri + 1], R = triRest[4 * tri + 2], S = triRest[4 * tri + 3];
            triA[e] = slot == 0 ? -P - R : slot == 1 ? P : R;
            triB[e] = slot == 0 ? -Q - S : slot == 1 ? Q : S;
        }
        // B's sparsity: each particle's hinge partners, sorted; then where each hinge's 4 × 4 entries land.
        bendStart = new int[n + 1];
        int[][] partners = new int[n][];
        for (int v = 0; v < n; v++) {
            java.util.TreeSet<Integer> set = new java.util.TreeSet<>();
            for (int e = hingeStart[v]; e < hingeStart[v + 1]; e++) {
                int base = hingeOf[e] - hingeOf[e] % hingeSlots;
                for (int q = 0; q < hingeSlots; q++) if (hingeParticle[base + q] >= 0) set.add(hingeParticle[base + q]);
            }
            partners[v] = set.stream().mapToInt(Integer::intValue).toArray();
            bendStart[v + 1] = bendStart[v] + partners[v].length;
        }
        bendColumn = new int[bendStart[n]];
        bendDiagonal = new int[n];
        for (int v = 0; v < n; v++) {
            System.arraycopy(partners[v], 0, bendColumn, bendStart[v], partners[v].length);
            int at = Arrays.binarySearch(partners[v], v);
            bendDiagonal[v] = at >= 0 ? bendStart[v] + at : -1;
        }
        bendValue = new double[bendStart[n]];
        final int slots2 = hingeSlots * hingeSlots;
        bendEntry = new int[slots2 * hingeCount];
        Arrays.fill(bendEntry, -1);
        for (int hg = 0; hg < hingeCount; hg++)
            for (int a = 0; a < hingeSlots; a++) {
                int v = hingeParticle[hingeSlots * hg + a];
                if (v < 0) continue;
                for (int b = 0; b < hingeSlots; b++) {
                    int u = hingeParticle[hingeSlots * hg + b];
                    if (u >= 0) bendEntry[slots2 * hg + hingeSlots * a + b] = bendStart[v] + Arrays.binarySearch(partners[v], u);
                }
            }

        stepLimit = new double[n];
        Arrays.fill(stepLimit, Double.POSITIVE_INFINITY);
        limitSteps(triStart, triOf, triParticle, 3);
        limitSteps(hingeStart, hingeOf, hingeParticle, hingeSlots);
        limitSteps(springStart, springOf, springParticle, 2);
        for (int v = 0; v < n; v++) stepLimit[v] *= MAX_STEP;

        colourOf = new int[n];
        colourMark = new int[n + 1];
        order = new int[n];
        colourStart = new int[n + 2];
        colour(null);
    }

    /**
     * Colours the particles: two that share an energy term, or a self-collision pair now listed, get
     * different colours (greedy, in index order; a colour is the smallest its earlier neighbours left free).
     * Then a particle's partner in a pair is never solved at the same time as it, so it is read as it is,
     * solved or not yet, and the result is the same on any thread count. Redone, without allocating, when
     * the self-collision's list changes.
     */
    private void colour(SelfCollision self) {
        Arrays.fill(colourOf, -1);
        int colours = 0;
        for (int v = 0; v < n; v++) {
            int stamp = v + 1;
            markNeighbours(v, triStart, triOf, triParticle, 3, stamp);
            // B's row of v lists every particle v shares a hinge or a patch with, once: a patch's twelve
            // particles are in some fifty of v's rows, which the colouring would visit each.
            for (int e = bendStart[v], end = bendStart[v + 1]; e < end; e++) {
                int u = bendColumn[e];
                if (colourOf[u] >= 0) colourMark[colourOf[u]] = stamp;
            }
            markNeighbours(v, springStart, springOf, springParticle, 2, stamp);
            if (self != null)
                for (int e = contactStart[v], end = contactStart[v + 1]; e < end; e++) {
                    int k = contactOf[e];
                    if (contacts.with(k) != self) continue;
                    int u = self.other(contacts.entry(k), v);
                    if (colourOf[u] >= 0) colourMark[colourOf[u]] = stamp;
                }
            int c = 0;
            while (colourMark[c] == stamp) c++;
            colourOf[v] = c;
            colours = Math.max(colours, c + 1);
        }
        colourCount = colours;
        Arrays.fill(colourStart, 0);
        for (int v = 0; v < n; v++) colourStart[colourOf[v] + 1]++;
        for (int c = 0; c < colours; c++) colourStart[c + 1] += colourStart[c];
        // colourStart[c] is where colour c begins; fill order by advancing a copy kept in colourMark.
        System.arraycopy(colourStart, 0, colourMark, 0, colours);
        for (int v = 0; v < n; v++) order[colourMark[colourOf[v]]++] = v;
        Arrays.fill(colourMark, 0);
    }

    /** For each particle, the entries element·arity + slot of the elements it is in (CSR, start filled). */
    private int[] incidences(int[] elementParticle, int arity, int[] start) {
        for (int e = 0; e < elementParticle.length; e++) if (elementParticle[e] >= 0) start[elementParticle[e] + 1]++;
        for (int v = 0; v < n; v++) start[v + 1] += start[v];
        int[] of = new int[start[n]], fill = Arrays.copyOf(start, n);
        for (int e = 0; e < elementParticle.length; e++) if (elementParticle[e] >= 0) of[fill[elementParticle[e]]++] = e;
        return of;
    }

    /** Lowers each particle's step limit to its distance (now, at rest) from every particle it shares an element with. */
    private void limitSteps(int[] start, int[] of, int[] elementParticle, int arity) {
        final double[] x = particles.x;
        for (int v = 0; v < n; v++)
            for (int k = start[v]; k < start[v + 1]; k++) {
                int base = of[k] - of[k] % arity;
                for (int q = 0; q < arity; q++) {
                    int u = elementParticle[base + q];
                    if (u < 0 || u == v) continue;
                    double dx = x[3 * v] - x[3 * u], dy = x[3 * v + 1] - x[3 * u + 1], dz = x[3 * v + 2] - x[3 * u + 2];
                    double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                    if (d > 0) stepLimit[v] = Math.min(stepLimit[v], d);
                }
            }
    }

    /** Stamps the colours of v's neighbours through one kind of element that are coloured already. */
    private void markNeighbours(int v, int[] start, int[] of, int[] elementParticle, int arity, int stamp) {
        for (int k = start[v]; k < start[v + 1]; k++) {
            int base = of[k] - of[k] % arity;
            for (int q = 0; q < arity; q++) {
                int p = elementParticle[base + q];
                if (p >= 0 && colourOf[p] >= 0) colourMark[colourOf[p]] = stamp;
            }
        }
    }

    int colours() { return colourCount; }

    /** The blocks projected after each iteration, and whether any of them has an energy (a compliance). */
    private final ConstraintBlock[] projectedBlocks;
    private boolean restHasEnergy;

    /** The blocks whose compliances the stiffnesses come from, and the sum of their material versions last derived. */
    private final ConstraintBlock[] stiffnessSources;
    private long refreshedFor = -1;

    /** Sum of the sources' material versions: it moves whenever any of them changes (each only counts up). */
    private long materialVersion() {
        long sum = 0;
        for (ConstraintBlock b : stiffnessSources) sum += b.materialVersion();
        for (ConstraintBlock b : projectedBlocks) sum += b.materialVersion();
        return sum;
    }

    /** Stiffnesses from the blocks' compliances (a fabric swap, a key or a fit may have changed them since the last step). */
    private void refreshStiffness() {
        for (int t = 0; t < triBlock.length; t++) {
            MembraneBlock m = triBlock[t];
            int i = triRow[t];
            double[] r = m.row;
            double k0 = 1 / m.compliance(i), k1 = 1 / m.compliance(i + 1), k2 = 1 / m.compliance(i + 2);
            // K = Σ_r r rᵀ/α_r for the rows (l₀₀, l₁₀, 0), (0, l₁₁, 0), (0, 0, l₂₂).
            double l00 = r[3 * i], l10 = r[3 * i + 1], l11 = r[3 * i + 4], l22 = r[3 * i + 8];
            triK[4 * t] = l00 * l00 * k0;
            triK[4 * t + 1] = l00 * l10 * k0;
            triK[4 * t + 2] = l10 * l10 * k0 + l11 * l11 * k1;
            triK[4 * t + 3] = l22 * l22 * k2;
        }
        Arrays.fill(bendValue, 0);
        for (int h = 0; h < hingeBlock.length; h++) {
            double k = 1 / hingeBlock[h].compliance(3 * hingeUnit[h]);
            for (int a = 0; a < hingeSlots; a++)
                for (int b = 0; b < hingeSlots; b++) {
                    int entry = bendEntry[hingeSlots * hingeSlots * h + hingeSlots * a + b];
                    if (entry >= 0) bendValue[entry] += k * hingeCoefficient[hingeSlots * h + a] * hingeCoefficient[hingeSlots * h + b];
                }
        }
        for (int s = 0; s < springBlock.length; s++) springStiffness[s] = 1 / springBlock[s].compliance(springRow[s]);
        restHasEnergy = false;
        for (ConstraintBlock b : projectedBlocks)
            for (int i = 0; i < b.count(); i++) if (b.compliance(i) > 0) restHasEnergy = true;
    }

    @Override public void solve(int substep, int iterations, StepProbe probe) {
        begin(substep);
        this.iterations = iterations;
        if (team != null && probe == null) {
            team.run(this);
            chargeHands();
            withoutEnergyGain();
            return;
        }
        if (bounded) budgetAndStart(0, 1);
        listener.afterSweep(substep, -1);
        for (int it = 0; it < iterations; it++) {
            if (probe == null) {
                for (int c = 0, nc = colours(); c < nc; c++) solveColour(c, 0, 1);
                rest.sweep(particles, ctx);
                gases.project(particles);
                contacts.projectFaces(particles, ctx.h);
                meetHeld();
            } else {
                // The colours' order, one particle at a time (its step moves it alone, with its contacts and pins).
                for (int k = 0; k < n; k++) {
                    solveParticle(order[k], inverseH2);
                    probe.check(order[k], firstFamily);
                }
                rest.sweep(particles, ctx, probe);
                gases.project(particles, probe);
                contacts.projectFaces(particles, ctx.h);
                meetHeld();
            }
            listener.afterSweep(substep, it);
        }
        if (bounded) sumEndEnergy(0, 1);
        chargeHands();
        withoutEnergyGain();
    }

    /** The substep's target y and start, its contacts by particle, and the colours if the pair list changed. */
    private void begin(int substep) {
        this.substep = substep;
        if (substep == 0) {
            long version = materialVersion();
            if (version != refreshedFor) { refreshStiffness(); refreshedFor = version; }
        }
        final double h = ctx.h, h2 = h * h;
        final double[] x = particles.x, w = particles.w, f = particles.force, y = target;
        final double gx = ctx.gravityX, gy = ctx.gravityY, gz = ctx.gravityZ;
        // y is where the prediction put the free particles; the iteration starts at x_prev + h v, without
        // this substep's external acceleration: at rest that is the rest, a fixed point.
        for (int i = 0; i < n; i++) {
            final int k = 3 * i;
            y[k] = x[k]; y[k + 1] = x[k + 1]; y[k + 2] = x[k + 2];
            final double wi = w[i];
            if (wi == 0) continue;
            x[k] -= h2 * (gx + wi * f[k]);
            x[k + 1] -= h2 * (gy + wi * f[k + 1]);
            x[k + 2] -= h2 * (gz + wi * f[k + 2]);
        }
        inverseH2 = 1 / h2;
        markHeld();
        for (int j = 0; j < heldCount; j++) System.arraycopy(attachments.target, 3 * heldBy[held[j]], x, 3 * held[j], 3);
        endMaterialKnown = stillIsLastEnd(substep);
        bounded = boundHolds();
        pushed = movingColliderInContact();
        endMaterialSummed = bounded;
        choosing = bounded && wary > 0;
        if (wary > 0) wary--;
        if (bounded && restHasEnergy) {
            stillProjectedEnergy = endMaterialKnown ? endProjectedEnergy : projectedEnergyAtStill();
            if (choosing) inertialProjectedEnergy = projectedEnergy();
        }
        contactOf = contacts.byParticle(n, contactStart, contactOf);
        SelfCollision self = contacts.self();
        long build = self == null ? -1 : self.builds();
        if (build != colouredForBuild) {
            colour(self);
            colouredForBuild = build;
        }
    }

    /**
     * Sums, on this thread's chunks, G at the still start (the budget {@link #withoutEnergyGain} holds the
     * substep to) and, while wary, at the inertial start, and starts the iterations from the lower: each
     * particle's step lowers G, so the iterations then end within the budget. From the inertial start they
     * may not: on a stiff membrane, carrying a turning triangle along its velocity stretches it, and
     * G(x_prev + h v) can exceed G(x_prev) by more than the sweeps take out. At rest the two starts are one
     * point, and a cloth in flight keeps the inertial start (moving it whole stretches nothing). The
     * inertial start's energy costs a sum over the material, so it is taken only for {@link #WARY} substeps
     * after the bound last had to step in (a calm scene never pays it; the bound is checked always). The
     * still start's material energy is the last substep's end's, where the free particles still are, unless
     * a step began since (a material or a position may have been set between steps) or a pin was moved.
     * The team waits after placing and after summing, and every thread takes the same decision from the
     * same sums.
     */
    private void budgetAndStart(int id, int threads) {
        final double[] x = particles.x;
        placeStill(id, threads);
        if (threads > 1) team.await();
        for (int c = id; c < CHUNKS; c += threads)
            stillEnergy[c] = energyChunk(stillStart, target, c, endMaterialKnown ? endMaterial[c] : materialChunk(stillStart, c), null);
        if (!choosing) return;
        for (int c = id; c < CHUNKS; c += threads) inertialEnergy[c] = energyChunk(x, target, c, materialChunk(x, c), null);
        if (threads > 1) team.await();
        double still = restHasEnergy ? stillProjectedEnergy : 0, inertial = restHasEnergy ? inertialProjectedEnergy : 0;
        for (int c = 0; c < CHUNKS; c++) { still += stillEnergy[c]; inertial += inertialEnergy[c]; }
        if (still < inertial) {
            final int from = 3 * share(n, id, threads), to = 3 * share(n, id + 1, threads);
            System.arraycopy(stillStart, from, x, from, to - from);
            if (threads > 1) team.await();
        }
    }

    /** This thread's chunks of the energy at the iterations' end, about x_prev: ½|v'|²_M + E(x'). */
    private void sumEndEnergy(int id, int threads) {
        final double[] x = particles.x;
        for (int c = id; c < CHUNKS; c += threads) {
            endMaterial[c] = materialChunk(x, c);
            endEnergy[c] = energyChunk(x, particles.prev, c, endMaterial[c], endInertia);
        }
    }

    /**
     * Puts every held particle back on its hand's target after the projected blocks moved it: a grab leads its
     * particle, as a pin does, so an iteration ends with it there (and the energy bound's still start is
     * admissible). A projected row that pulled it away would otherwise fight the hand once per iteration, each
     * round an impulse of m δx/h, and at a small substep that is speed from nowhere.
     */
    private void meetHeld() {
        for (int i = 0, na = attachments.count(); i < na; i++) if (!(attachments.compliance(i) > 0)) attachments.project(i, particles, ctx);
    }

    /** {@link #heldBy} for this substep: each free particle's first hard attachment (several on one would disagree only where no step can meet them). */
    private void markHeld() {
        for (int j = 0; j < heldCount; j++) heldBy[held[j]] = -1;
        heldCount = 0;
        for (int i = 0, na = attachments.count(); i < na; i++) {
            final int v = attachments.particle(i, 0);
            if (!(attachments.compliance(i) > 0) && heldBy[v] < 0 && particles.w[v] != 0) { heldBy[v] = i; held[heldCount++] = v; }
        }
    }

    /**
     * Gives each hand the force it exerted: what keeps its particle on the target against the particle's
     * inertia and the energies, −f = m(x − y)/h² + ∇E (the residual its own step would have taken out), added
     * to what the projected blocks' pulls cost it ({@link #meetHeld}'s corrections), so the hand's work counts
     * what it put into the cloth.
     */
    private void chargeHands() {
        for (int j = 0; j < heldCount; j++) {
            final int v = held[j];
            attachments.addForce(heldBy[v], handForce[3 * v], handForce[3 * v + 1], handForce[3 * v + 2]);
        }
    }

    /** Whether the still start's material energy is the last substep's end's: a later substep of the same step, no pin or held particle moved. */
    private boolean stillIsLastEnd(int substep) {
        if (substep == 0 || !endMaterialSummed) return false;
        final double[] x = particles.x, prev = particles.prev, w = particles.w, t = attachments.target;
        for (int v = 0; v < n; v++) {
            final int k = 3 * v, hand = heldBy[v];
            if (hand >= 0) {
                final int j = 3 * hand;
                if (t[j] != prev[k] || t[j + 1] != prev[k + 1] || t[j + 2] != prev[k + 2]) return false;
            } else if (w[v] == 0 && (x[k] != prev[k] || x[k + 1] != prev[k + 1] || x[k + 2] != prev[k + 2])) return false;
        }
        return true;
    }

    /**
     * The energy sums are taken in this many chunks, each summed alone and then added in chunk order, so that
     * they are the same bits on any number of threads (a thread takes every threads-th chunk).
     */
    private static final int CHUNKS = 8;
    /** Per chunk: G at the still start; the energy at the iterations' end and, of it, the inertia about x_prev (½|v'|²_M). */
    private final double[] stillEnergy = new double[CHUNKS], inertialEnergy = new double[CHUNKS], endEnergy = new double[CHUNKS], endInertia = new double[CHUNKS];
    /** Per chunk, the material's energy at the last substep's end; whether it was summed, and is this substep's still start's. */
    private final double[] endMaterial = new double[CHUNKS];
    private boolean endMaterialSummed, endMaterialKnown;
    /** Whether the energy bound holds this substep ({@link #boundHolds}), and whether its start is chosen ({@link #budgetAndStart}). */
    private boolean bounded, choosing;
    /** Whether a moving collider is in contact this substep: its work in the substep enters the bound's budget. */
    private boolean pushed;
    /** Substeps after the bound took speed out during which the start is chosen; how many are left. */
    static final int WARY = 20;
    private int wary;
    /** The projected blocks' energy at the still start, the inertial start and the last substep's end; where x is kept meanwhile. */
    private double stillProjectedEnergy, inertialProjectedEnergy, endProjectedEnergy;
    private final double[] keptPositions;

    /**
     * ½ Σ C²/α over the projected blocks' compliant rows (a shear, a dihedral: XPBD's energy, which these
     * blocks hold by projection) at the particles' positions, on one thread in block order.
     */
    private double projectedEnergy() {
        double sum = 0;
        for (ConstraintBlock b : projectedBlocks)
            for (int i = 0, count = b.count(); i < count; i++) {
                final double alpha = b.compliance(i);
                if (!(alpha > 0)) continue;
                final double c = b.evaluate(i, particles);
                sum += c * c / alpha;
            }
        return 0.5 * sum;
    }

    /** The projected blocks' energy at the still start: the blocks read the particles, so the start is put there for it. */
    private double projectedEnergyAtStill() {
        final double[] x = particles.x;
        placeStill(0, 1);
        System.arraycopy(x, 0, keptPositions, 0, 3 * n);
        System.arraycopy(stillStart, 0, x, 0, 3 * n);
        double energy = projectedEnergy();
        System.arraycopy(keptPositions, 0, x, 0, 3 * n);
        return energy;
    }

    /**
     * Takes out of the substep's new velocity what the iterations added to the energy. Implicit Euler's
     * solution x' of min G, with v' = (x' − x_prev)/h, has ½|v'|²_M + E(x') ≤ ½|ṽ|²_M + E(x_prev) − ½|v' − ṽ|²_M
     * for a convex energy (from ∇G(x') = 0; likewise at a contact with a still solid, where x_prev is
     * admissible), where ṽ = v + h a is the velocity after the external forces and the right side is G(x_prev):
     * the step dissipates (E here includes the projected blocks' compliant rows). A few sweeps stop short of x', and on a cloth much stiffer than its inertia the
     * error they leave, which they shrink in G's norm, can grow in the masses' norm: as velocity. Compounded
     * over the steps, a strongly anisotropic membrane (E2/E1 = 4e7) ran away (docs/robustness.md). So where
     * the left side exceeds G(x_prev), the free particles' velocities are scaled to meet it (positions are
     * kept; the velocity update reads x − x_prev, so x_prev moves), as Dinev, Liu and Kavan 2018, "Stabilizing
     * Integrators for Real-Time Physics", bound an integrator's energy. Not where the bound does not hold for
     * the exact step either ({@link #boundHolds}).
     */
    private void withoutEnergyGain() {
        if (!bounded) return;
        double budget = 0, end = 0, kinetic = 0;
        for (int c = 0; c < CHUNKS; c++) { budget += stillEnergy[c]; end += endEnergy[c]; kinetic += endInertia[c]; }
        if (restHasEnergy) {
            endProjectedEnergy = projectedEnergy();
            budget += stillProjectedEnergy;
            end += endProjectedEnergy;
        }
        if (pushed) budget += Math.max(0, contacts.workInSubstep(particles, ctx.h));
        if (end <= budget || kinetic == 0) return;
        wary = WARY;
        final double[] x = particles.x, prev = particles.prev, w = particles.w;
        if (end - kinetic > budget) {
            // The sweeps left more energy in the cloth's strain alone than staying put has: no speed can pay for
            // that. Undoing the substep froze cloth in mid-air, and keeping the strain at rest stored the energy
            // the sweeps made, to come back as speed (docs/robustness.md), so the substep is solved again by
            // Gauss–Seidel, which meets each row in turn and does not climb, and the next ones choose their start.
            redoByGaussSeidel();
            return;
        }
        final double scale = Math.sqrt(Math.max(0, budget - (end - kinetic)) / kinetic);
        for (int v = 0; v < n; v++) {
            if (w[v] == 0 || heldBy[v] >= 0) continue;
            for (int k = 3 * v; k < 3 * v + 3; k++) prev[k] = x[k] - scale * (x[k] - prev[k]);
        }
    }

    /**
     * Solves the substep again from its prediction y by XPBD's Gauss–Seidel sweeps (the same rows, the same
     * sweep count): λ back to 0, the hands' forces and the contacts' moves so far forgotten, so what is counted
     * for their work is the redone solve's.
     */
    private void redoByGaussSeidel() {
        System.arraycopy(target, 0, particles.x, 0, 3 * n); // the free particles at y, the pinned where they are
        for (int b = 0, nb = body.size(); b < nb; b++) body.get(b).beginSubstep(ctx);
        attachments.beginSubstep(ctx);
        attachments.forgetForces();
        contacts.forgetMoves();
        gaussSeidel.solve(substep, iterations, null);
        endMaterialSummed = false;
    }

    /**
     * Whether the bound holds for the exact step: no enclosed gas. A moving collider in contact does work on
     * the cloth that is not in G, so it does not lift the bound either: its work in the substep, counted as the
     * simulation counts it (force of its projections times each particle's move), is added to the budget
     * ({@link #pushed}). Without it a solid at 350 m/s hitting a stiff chain left the sweeps unguarded (fuzz
     * seed 233: 8e5 J where the solid's counted work was 1.6e4 J); with it that case ends nearer its bound
     * but still over it (3.1e5 J against 2.8e5 J at step 7), a case still open. A hard attachment (a grab)
     * does not lift the bound: its particle ends the substep on the target, so the still start with it there
     * is admissible, and the bound is then the free particles' (see {@link #energyChunk}).
     */
    private boolean boundHolds() {
        return gases.count() == 0; // a gas's energy, p₀V − nRT ln V, is not in G: its work would read as a gain
    }

    /** Whether a collider that moves (a scripted solid) touches the cloth this substep: its work enters the budget. */
    private boolean movingColliderInContact() {
        for (int k = 0, nc = contacts.count(); k < nc; k++) if (contacts.with(k).moving()) return true;
        return false;
    }

    /**
     * Share {@code id} of {@code shares} of the still start, where G(x_prev) = ½|ṽ|²_M + E(x_prev) is summed:
     * the free particles where the substep began, the pinned where they are now and the held on their targets
     * (a kinematic pin's or a hand's work is in G then). Every share is placed before any energy is summed
     * (the team waits between).
     */
    private void placeStill(int id, int shares) {
        final double[] x = particles.x, w = particles.w, prev = particles.prev, still = stillStart, t = attachments.target;
        for (int v = share(n, id, shares), end = share(n, id + 1, shares); v < end; v++) {
            final int k = 3 * v, hand = heldBy[v];
            final double[] from = hand >= 0 ? t : w[v] != 0 ? prev : x;
            final int j = hand >= 0 ? 3 * hand : k;
            still[k] = from[j]; still[k + 1] = from[j + 1]; still[k + 2] = from[j + 2];
        }
    }

    /** The first of {@code count} items in share {@code id} of {@code shares}. */
    private static int share(int count, int id, int shares) { return (int) ((long) count * id / shares); }

    /**
     * Chunk {@code id} of {@link #CHUNKS} of the step's energy at positions x about a: the free particles'
     * inertia Σ mᵢ|xᵢ − aᵢ|²/(2h²) (also written to {@code inertiaOut[id]} when given; not a held particle's:
     * it is on its target both at the still start z and at the exact step's end x', so its inertia is the same
     * on both sides of G(x') + ½|z − x'|²_M/h² ≤ G(z) and cancels, leaving the free particles'
     * ½|v'|²_M + E(x') ≤ ½|ṽ|²_M + E(z)), the material's energy
     * ({@code material}, from {@link #materialChunk}), the compliant attachments' and the penalties of the
     * listed pair contacts. Friction dissipates, and solids and the projected blocks are met exactly: they have
     * no energy here. The chunks sum to the whole.
     */
    private double energyChunk(double[] x, double[] about, int id, double material, double[] inertiaOut) {
        final int shares = CHUNKS;
        final double[] w = particles.w;
        final int from = share(n, id, shares), to = share(n, id + 1, shares);
        double inertial = 0, elastic = 0;
        for (int v = from; v < to; v++) {
            if (w[v] == 0 || heldBy[v] >= 0) continue;
            final int k = 3 * v;
            double dx = x[k] - about[k], dy = x[k + 1] - about[k + 1], dz = x[k + 2] - about[k + 2];
            inertial += (dx * dx + dy * dy + dz * dz) / w[v];
        }
        for (int i = share(attachments.count(), id, shares), end = share(attachments.count(), id + 1, shares); i < end; i++) {
            final double alpha = attachments.compliance(i);
            if (!(alpha > 0)) continue;
            final int kv = 3 * attachments.particle(i, 0);
            double dx = x[kv] - attachments.target[3 * i], dy = x[kv + 1] - attachments.target[3 * i + 1], dz = x[kv + 2] - attachments.target[3 * i + 2];
            elastic += (dx * dx + dy * dy + dz * dz) / alpha;
        }
        for (int k = share(contacts.count(), id, shares), end = share(contacts.count(), id + 1, shares); k < end; k++) {
            final Collider with = contacts.with(k);
            if (!(with instanceof SelfCollision)) continue;
            final SelfCollision self = (SelfCollision) with;
            final int a = contacts.particle(k), b = self.other(contacts.entry(k), a);
            final double wab = w[a] + w[b];
            if (wab == 0) continue;
            double dx = x[3 * a] - x[3 * b], dy = x[3 * a + 1] - x[3 * b + 1], dz = x[3 * a + 2] - x[3 * b + 2];
            double c = Math.sqrt(dx * dx + dy * dy + dz * dz) - self.thickness;
            if (c < 0) elastic += CONTACT_STIFFNESS * inverseH2 / wab * c * c;
        }
        inertial *= 0.5 * inverseH2;
        if (inertiaOut != null) inertiaOut[id] = inertial;
        return inertial + 0.5 * elastic + material;
    }

    /**
     * Chunk {@code id} of {@link #CHUNKS} of the material's energy at positions x, each term once: the
     * membranes, the hinges (½ xᵀBx per axis), springs and tethers. Within a step it changes only with x.
     */
    private double materialChunk(double[] x, int id) {
        final int shares = CHUNKS;
        final double[] w = particles.w;
        final int from = share(n, id, shares), to = share(n, id + 1, shares);
        double elastic = 0;
        for (int t = share(triBlock.length, id, shares), end = share(triBlock.length, id + 1, shares); t < end; t++) {
            final int a0 = 3 * triParticle[3 * t], a1 = 3 * triParticle[3 * t + 1], a2 = 3 * triParticle[3 * t + 2];
            final double P = triRest[4 * t], Q = triRest[4 * t + 1], R = triRest[4 * t + 2], S = triRest[4 * t + 3];
            double e1x = x[a1] - x[a0], e1y = x[a1 + 1] - x[a0 + 1], e1z = x[a1 + 2] - x[a0 + 2];
            double e2x = x[a2] - x[a0], e2y = x[a2 + 1] - x[a0 + 1], e2z = x[a2 + 2] - x[a0 + 2];
            double ux = e1x * P + e2x * R, uy = e1y * P + e2y * R, uz = e1z * P + e2z * R;
            double wx = e1x * Q + e2x * S, wy = e1y * Q + e2y * S, wz = e1z * Q + e2z * S;
            double euu = 0.5 * (ux * ux + uy * uy + uz * uz - 1), eww = 0.5 * (wx * wx + wy * wy + wz * wz - 1);
            double uw = ux * wx + uy * wy + uz * wz;
            elastic += triK[4 * t] * euu * euu + 2 * triK[4 * t + 1] * euu * eww + triK[4 * t + 2] * eww * eww + triK[4 * t + 3] * uw * uw;
        }
        for (int v = from; v < to; v++) {
            final int kv = 3 * v, d = bendDiagonal[v];
            // B is symmetric and a row's columns are sorted: its diagonal once, the columns past it twice.
            if (d >= 0) {
                double bx = 0, by = 0, bz = 0;
                for (int e = d + 1, end = bendStart[v + 1]; e < end; e++) {
                    final int u = 3 * bendColumn[e];
                    final double b = bendValue[e];
                    bx += b * x[u]; by += b * x[u + 1]; bz += b * x[u + 2];
                }
                final double bd = bendValue[d];
                elastic += x[kv] * (2 * bx + bd * x[kv]) + x[kv + 1] * (2 * by + bd * x[kv + 1]) + x[kv + 2] * (2 * bz + bd * x[kv + 2]);
            }
            if (w[v] == 0) continue;
            for (int e = tetherStart[v], end = tetherStart[v + 1]; e < end; e++) {
                final int ka = 3 * tetherAnchor[tetherOf[e]];
                double dx = x[kv] - x[ka], dy = x[kv + 1] - x[ka + 1], dz = x[kv + 2] - x[ka + 2];
                double c = Math.sqrt(dx * dx + dy * dy + dz * dz) - tetherDistance[tetherOf[e]];
                if (c > 0) elastic += HARD_STIFFNESS * inverseH2 / w[v] * c * c;
            }
        }
        for (int s = share(springStiffness.length, id, shares), end = share(springStiffness.length, id + 1, shares); s < end; s++) {
            final int a = 3 * springParticle[2 * s], b = 3 * springParticle[2 * s + 1];
            double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
            double c = Math.sqrt(dx * dx + dy * dy + dz * dz) - springRest[s];
            elastic += springStiffness[s] * c * c;
        }
        return 0.5 * elastic;
    }

    /**
     * A substep's iterations on the team: each colour split into shares, the projected blocks on the caller.
     * What the job decides by is read once, at its top, into locals (the team's closing barrier keeps the
     * caller from changing these fields before every helper is out; reading them once says so here too).
     */
    @Override public void work(int id, Team t) {
        final int threads = t.threads(), colours = colours(), iterations = this.iterations;
        final boolean bounded = this.bounded;
        if (bounded) budgetAndStart(id, threads);
        for (int it = 0; it < iterations; it++) {
            for (int c = 0; c < colours; c++) {
                solveColour(c, id, threads);
                t.await();
            }
            if (id == 0) {
                rest.sweep(particles, ctx);
                gases.project(particles);
                contacts.projectFaces(particles, ctx.h);
                meetHeld();
            }
            t.await();
        }
        if (bounded) {
            sumEndEnergy(id, threads);
            t.await(); // the caller sums every chunk when its own share returns
        }
    }

    /** The particles of colour c, share id of {@code shares} (each thread takes a contiguous share). */
    void solveColour(int c, int id, int shares) {
        int from = colourStart[c], size = colourStart[c + 1] - from;
        int lo = from + (int) ((long) size * id / shares), hi = from + (int) ((long) size * (id + 1) / shares);
        for (int k = lo; k < hi; k++) solveParticle(order[k], inverseH2);
    }

    /** One Newton step of particle v on the step's energy with every other particle held. */
    private void solveParticle(int v, double inverseH2) {
        final double[] x = particles.x, y = target;
        final double wv = particles.w[v];
        if (wv == 0) return;
        final int kv = 3 * v;
        final double inertia = inverseH2 / wv;
        double fx = -inertia * (x[kv] - y[kv]), fy = -inertia * (x[kv + 1] - y[kv + 1]), fz = -inertia * (x[kv + 2] - y[kv + 2]);
        double h00 = inertia, h01 = 0, h02 = 0, h11 = inertia, h12 = 0, h22 = inertia;

        // Membrane triangles: U = ½ εᵀ K ε, ε = (E_uu, E_vv, γ); ∂ε/∂x_v = (a f_u, b f_v, a f_v + b f_u).
        for (int e = triStart[v], end = triStart[v + 1]; e < end; e++) {
            final int t = triOf[e] / 3;
            final int a0 = 3 * triParticle[3 * t], a1 = 3 * triParticle[3 * t + 1], a2 = 3 * triParticle[3 * t + 2];
            final double P = triRest[4 * t], Q = triRest[4 * t + 1], R = triRest[4 * t + 2], S = triRest[4 * t + 3];
            final double a = triA[e], b = triB[e];
            double e1x = x[a1] - x[a0], e1y = x[a1 + 1] - x[a0 + 1], e1z = x[a1 + 2] - x[a0 + 2];
            double e2x = x[a2] - x[a0], e2y = x[a2 + 1] - x[a0 + 1], e2z = x[a2 + 2] - x[a0 + 2];
            double ux = e1x * P + e2x * R, uy = e1y * P + e2y * R, uz = e1z * P + e2z * R;
            double wx = e1x * Q + e2x * S, wy = e1y * Q + e2y * S, wz = e1z * Q + e2z * S;
            double uu = ux * ux + uy * uy + uz * uz, ww = wx * wx + wy * wy + wz * wz, uw = ux * wx + uy * wy + uz * wz;
            double euu = 0.5 * (uu - 1), eww = 0.5 * (ww - 1);
            final double k00 = triK[4 * t], k01 = triK[4 * t + 1], k11 = triK[4 * t + 2], k22 = triK[4 * t + 3];
            double s0 = k00 * euu + k01 * eww, s1 = k01 * euu + k11 * eww, s2 = k22 * uw; // σ = K ε (K has no normal–shear coupling)
            double cu = s0 * a + s2 * b, cw = s1 * b + s2 * a;                          // ∂U/∂x_v = cu f_u + cw f_v
            fx -= cu * ux + cw * wx; fy -= cu * uy + cw * wy; fz -= cu * uz + cw * wz;
            // Gauss–Newton: Bᵀ K B with B's columns a f_u, b f_v, a f_v + b f_u, written in the basis (f_u, f_v).
            double muu = a * a * k00 + b * b * k22, muw = a * b * (k01 + k22), mww = b * b * k11 + a * a * k22;
            double geometric = s0 * a * a + s1 * b * b + 2 * s2 * a * b;
            if (geometric < 0) geometric = 0;
            h00 += muu * ux * ux + 2 * muw * ux * wx + mww * wx * wx + geometric;
            h11 += muu * uy * uy + 2 * muw * uy * wy + mww * wy * wy + geometric;
            h22 += muu * uz * uz + 2 * muw * uz * wz + mww * wz * wz + geometric;
            h01 += muu * ux * uy + muw * (ux * wy + wx * uy) + mww * wx * wy;
            h02 += muu * ux * uz + muw * (ux * wz + wx * uz) + mww * wx * wz;
            h12 += muu * uy * uz + muw * (uy * wz + wy * uz) + mww * wy * wz;
        }

        // Quadratic hinges: f = −Σ_u B_vu x_u per axis, H += diag(B_vv). Summed in two interleaved halves: a
        // patch couples a particle to some thirty, and one running sum waits on each of its additions in turn.
        {
            double gx = 0, gy = 0, gz = 0;
            int e = bendStart[v];
            final int end = bendStart[v + 1];
            for (; e + 1 < end; e += 2) {
                final int u = 3 * bendColumn[e], u2 = 3 * bendColumn[e + 1];
                final double b = bendValue[e], b2 = bendValue[e + 1];
                fx -= b * x[u]; fy -= b * x[u + 1]; fz -= b * x[u + 2];
                gx -= b2 * x[u2]; gy -= b2 * x[u2 + 1]; gz -= b2 * x[u2 + 2];
            }
            if (e < end) {
                final int u = 3 * bendColumn[e];
                final double b = bendValue[e];
                fx -= b * x[u]; fy -= b * x[u + 1]; fz -= b * x[u + 2];
            }
            fx += gx; fy += gy; fz += gz;
            final int d = bendDiagonal[v];
            if (d >= 0) { final double bd = bendValue[d]; h00 += bd; h11 += bd; h22 += bd; }
        }

        // Springs: U = ½ k (|d| − L)², d = x_v − x_other; H = k (n nᵀ + [C/|d|]₊ (I − n nᵀ)).
        for (int e = springStart[v], end = springStart[v + 1]; e < end; e++) {
            final int sp = springOf[e] >> 1, slot = springOf[e] & 1;
            final int other = 3 * springParticle[2 * sp + 1 - slot];
            double dx = x[kv] - x[other], dy = x[kv + 1] - x[other + 1], dz = x[kv + 2] - x[other + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (len < DistanceBlock.MIN_LENGTH) continue;
            final double k = springStiffness[sp], inv = 1 / len;
            double nx = dx * inv, ny = dy * inv, nz = dz * inv, C = len - springRest[sp];
            fx -= k * C * nx; fy -= k * C * ny; fz -= k * C * nz;
            double tangential = C > 0 ? k * C * inv : 0, along = k - tangential;
            h00 += along * nx * nx + tangential; h11 += along * ny * ny + tangential; h22 += along * nz * nz + tangential;
            h01 += along * nx * ny; h02 += along * nx * nz; h12 += along * ny * nz;
        }

        // Tethers, a stiff penalty on the stretch past the rest distance to a pinned anchor: U = ½ k C₊².
        for (int e = tetherStart[v], end = tetherStart[v + 1]; e < end; e++) {
            final int tt = tetherOf[e], ka = 3 * tetherAnchor[tt];
            double dx = x[kv] - x[ka], dy = x[kv + 1] - x[ka + 1], dz = x[kv + 2] - x[ka + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz), C = len - tetherDistance[tt];
            if (C <= 0 || len < DistanceBlock.MIN_LENGTH) continue;
            final double k = HARD_STIFFNESS * inertia, inv = 1 / len;
            double nx = dx * inv, ny = dy * inv, nz = dz * inv;
            fx -= k * C * nx; fy -= k * C * ny; fz -= k * C * nz;
            double tangential = k * C * inv, along = k - tangential;
            h00 += along * nx * nx + tangential; h11 += along * ny * ny + tangential; h22 += along * nz * nz + tangential;
            h01 += along * nx * ny; h02 += along * nx * nz; h12 += along * ny * nz;
        }

        // Compliant attachments, U = ½|x − t|²/α (a hard one holds its particle: heldBy).
        for (int e = attachedStart[v], end = attachedStart[v + 1]; e < end; e++) {
            final int i = attachedOf[e];
            final double alpha = attachments.compliance(i);
            if (!(alpha > 0)) continue;
            final double k = 1 / alpha;
            fx -= k * (x[kv] - attachments.target[3 * i]); fy -= k * (x[kv + 1] - attachments.target[3 * i + 1]); fz -= k * (x[kv + 2] - attachments.target[3 * i + 2]);
            h00 += k; h11 += k; h22 += k;
        }

        // Contacts between two particles of the cloth: a penalty ½k C² while C = |x_v − x_u| − t < 0, with
        // friction as a dissipative force on the pair's tangential slip over the substep, its normal force lagged
        // (Li et al. 2020, "Incremental Potential Contact", §5): f_t = −μ k(−C) f₁(|u|)/|u| · u, f₁ smoothing the
        // stick (|u| < ε) into the slide. The partner has another colour (the colouring takes the pairs in), so it
        // is read where it is now, solved before or after this particle, never at the same time.
        for (int e = contactStart[v], end = contactStart[v + 1]; e < end; e++) {
            final int k = contactOf[e];
            final Collider with = contacts.with(k);
            if (!(with instanceof SelfCollision)) continue;
            final SelfCollision self = (SelfCollision) with;
            final int u = self.other(contacts.entry(k), v), ku = 3 * u;
            double dx = x[kv] - x[ku], dy = x[kv + 1] - x[ku + 1], dz = x[kv + 2] - x[ku + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double C = len - self.thickness;
            if (C >= 0 || len < DistanceBlock.MIN_LENGTH) continue;
            final double kc = CONTACT_STIFFNESS * inverseH2 / (wv + particles.w[u]);
            double nx = dx / len, ny = dy / len, nz = dz / len, push = -kc * C;
            fx += push * nx; fy += push * ny; fz += push * nz;
            h00 += kc * nx * nx; h11 += kc * ny * ny; h22 += kc * nz * nz;
            h01 += kc * nx * ny; h02 += kc * nx * nz; h12 += kc * ny * nz;
            final double[] prev = particles.prev;
            double rx = (x[kv] - prev[kv]) - (x[ku] - prev[ku]), ry = (x[kv + 1] - prev[kv + 1]) - (x[ku + 1] - prev[ku + 1]), rz = (x[kv + 2] - prev[kv + 2]) - (x[ku + 2] - prev[ku + 2]);
            double along = rx * nx + ry * ny + rz * nz;
            double tx = rx - along * nx, ty = ry - along * ny, tz = rz - along * nz;
            double slip = Math.sqrt(tx * tx + ty * ty + tz * tz), epsilon = SLIP * ctx.h;
            double mu = slip < epsilon ? self.staticFriction : self.kineticFriction;
            // f₁(s)/s: 2/ε − s/ε² below ε, 1/s above.
            double f1OverS = slip < epsilon ? 2 / epsilon - slip / (epsilon * epsilon) : 1 / slip;
            double kt = mu * push * f1OverS;
            if (kt > 0) {
                fx -= kt * tx; fy -= kt * ty; fz -= kt * tz;
                // The tangent plane's projector I − n nᵀ, times kt.
                h00 += kt * (1 - nx * nx); h11 += kt * (1 - ny * ny); h22 += kt * (1 - nz * nz);
                h01 -= kt * nx * ny; h02 -= kt * nx * nz; h12 -= kt * ny * nz;
            }
        }

        if (heldBy[v] >= 0) { // the hand holds it on the target: it takes the force, the particle no step
            handForce[kv] = -fx; handForce[kv + 1] = -fy; handForce[kv + 2] = -fz;
            return;
        }
        // H Δ = f by the symmetric 3 × 3 inverse (H is positive definite: inertia plus positive terms).
        double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        double det = h00 * c00 + h01 * c01 + h02 * c02;
        if (!(det > 0)) return;
        double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
        double inv = 1 / det;
        double dx = (c00 * fx + c01 * fy + c02 * fz) * inv, dy = (c01 * fx + c11 * fy + c12 * fz) * inv, dz = (c02 * fx + c12 * fy + c22 * fz) * inv;
        double step = Math.sqrt(dx * dx + dy * dy + dz * dz), limit = stepLimit[v];
        if (step > limit) { double scale = limit / step; dx *= scale; dy *= scale; dz *= scale; }
        x[kv] += dx; x[kv + 1] += dy; x[kv + 2] += dz;
        // Its contacts with solids at once, so the particles solved after it never see it inside a solid.
        for (int e = contactStart[v], end = contactStart[v + 1]; e < end; e++) {
            final int k = contactOf[e];
            final Collider with = contacts.with(k);
            if (!with.internal()) contacts.projectOne(particles, k, v, ctx.h);
        }
    }
}
