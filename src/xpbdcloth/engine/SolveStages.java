package xpbdcloth.engine;

import java.util.ArrayList;
import java.util.List;

/**
 * Chooses a simulation's solve stage for its settings and constraints, and keeps what a choice costs to
 * make: the coloured order, the global solver and the helper threads. A stage is chosen again only when
 * the constraints ({@link ConstraintSet}'s versions), the solver type, the order, the thread count, the
 * PCG settings or the sweep listener changed, never by branches inside the substep loop. Grabbing keeps
 * the global solver and the cloth's colouring (attachments are not in either).
 */
final class SolveStages {
    private final ConstraintSet constraints;
    private final Particles particles;
    private final SolverContext ctx;
    private final EnclosedGases gases;
    private final ContactSet contacts;
    private Colouring clothColouring;
    private long clothColouringVersion = -1;
    private SweepOrder coloured;
    private long colouredVersion = -1;
    private GlobalSolver global;
    private long globalVersion = -1;
    private int globalSetups;
    private Team team;
    private SolveStage stage;
    /** What {@link #stage} was chosen for (compared each step without allocating). */
    private SolverType chosenType;
    private boolean chosenColoured;
    private int chosenThreads;
    private SweepListener chosenListener;
    private GlobalSolver chosenGlobal;
    private long chosenVersion = -1;

    SolveStages(ConstraintSet constraints, Particles particles, SolverContext ctx, EnclosedGases gases, ContactSet contacts) {
        this.constraints = constraints;
        this.particles = particles;
        this.ctx = ctx;
        this.gases = gases;
        this.contacts = contacts;
    }

    /** The solve stage for these settings and the current constraints, made only if one of them changed. */
    SolveStage stage(SolverSettings settings, SweepListener listener) {
        SolverType type = settings.solver();
        // A gas couples its whole surface through one volume, and vertex block descent has no term for it (its
        // per-particle steps and the gas's row fought: a balloon crumpled to strains of 3): Gauss–Seidel solves it.
        if (type == SolverType.VERTEX_BLOCK_DESCENT && gases.count() > 0) type = SolverType.GAUSS_SEIDEL;
        boolean colouredOrder = settings.order() == ConstraintOrder.COLOURED;
        int threads = settings.threads();
        GlobalSolver g = type.isGlobal() ? globalSolver(settings) : null; // remade if the PCG settings changed
        if (stage != null && type == chosenType && colouredOrder == chosenColoured && threads == chosenThreads
                && listener == chosenListener && g == chosenGlobal && constraints.version() == chosenVersion) return stage;
        AttachmentBlock attachments = constraints.attachments();
        // The team runs a substep's sweeps in one go, so a listener to single sweeps gets a sequential stage.
        Team helpers = listener == SweepListener.NONE ? team(threads) : null;
        if (type == SolverType.VERTEX_BLOCK_DESCENT) {
            SequentialSweeps gaussSeidel = new SequentialSweeps(constraints.order(), particles, ctx, gases, contacts, listener);
            stage = new VertexBlockDescent(constraints.cloth(), attachments, particles, ctx, gases, contacts, listener, helpers, gaussSeidel);
        } else if (g != null) {
            List<ConstraintBlock> local = new ArrayList<>();
            for (ConstraintBlock blk : constraints.cloth()) if (!GlobalSolver.takes(blk)) local.add(blk);
            SequentialSweeps rest = new SequentialSweeps(SweepOrder.asBuilt(List.of(attachments)), particles, ctx, gases, contacts, listener);
            SequentialSweeps all = new SequentialSweeps(constraints.order(), particles, ctx, gases, contacts, listener);
            stage = new GlobalIterations(g, SweepOrder.asBuilt(local), rest, all, contacts, particles, ctx, listener);
        } else if (!colouredOrder) {
            stage = new SequentialSweeps(constraints.order(), particles, ctx, gases, contacts, listener);
        } else {
            SweepOrder col = colouring();
            SequentialSweeps sequential = new SequentialSweeps(col, particles, ctx, gases, contacts, listener);
            stage = helpers == null ? sequential : new ParallelColouredSweeps(col, helpers, particles, ctx, gases, contacts, sequential);
        }
        chosenType = type;
        chosenColoured = colouredOrder;
        chosenThreads = threads;
        chosenListener = listener;
        chosenGlobal = g;
        chosenVersion = constraints.version();
        return stage;
    }

    /** The cloth's colouring (kept while the cloth's constraints stay) and then the attachments'. */
    SweepOrder colouring() {
        if (clothColouringVersion != constraints.clothVersion()) {
            clothColouring = Colouring.of(constraints.cloth(), particles.count());
            clothColouringVersion = constraints.clothVersion();
        }
        if (colouredVersion != constraints.version()) {
            coloured = SweepOrder.coloured(List.of(clothColouring, Colouring.of(List.of(constraints.attachments()), particles.count())));
            colouredVersion = constraints.version();
        }
        return coloured;
    }

    private GlobalSolver globalSolver(SolverSettings settings) {
        boolean mg = settings.solver() == SolverType.MULTIGRID_PCG;
        if (global == null || globalVersion != constraints.clothVersion() || global.multigrid() != mg
                || global.tolerance() != settings.pcgTolerance() || global.maxIterations() != settings.pcgMaxIterations()) {
            List<ConstraintBlock> taken = new ArrayList<>();
            for (ConstraintBlock b : constraints.cloth()) if (GlobalSolver.takes(b)) taken.add(b);
            global = new GlobalSolver(ConstraintRows.of(taken), particles.count(), mg, settings.pcgTolerance(), settings.pcgMaxIterations());
            globalVersion = constraints.clothVersion();
            globalSetups++;
        }
        return global;
    }

    /** The helper threads for {@code threads} (made once per thread count), or null for one thread. */
    Team team(int threads) {
        if (threads <= 1) return null;
        if (team == null || team.threads() != threads) {
            if (team != null) team.close();
            team = new Team(threads);
        }
        return team;
    }

    /** The last global solver built (kept while another solver type is chosen), or null. */
    GlobalSolver global() { return global; }

    /** The solver the stage chosen last runs (the settings' unless a gas made it Gauss–Seidel), or null before any. */
    SolverType inUse() { return chosenType; }

    /** The global solver of the stage chosen last (the last step's), or null. */
    GlobalSolver globalInUse() { return chosenGlobal; }

    int globalSetups() { return globalSetups; }

    void close() {
        if (team != null) team.close();
        team = null;
    }
}
