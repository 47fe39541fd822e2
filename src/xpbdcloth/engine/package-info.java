/**
 * The engine: plain Java, no Processing. SI units throughout (m, s, kg, N).
 * <ul>
 *   <li>{@link xpbdcloth.engine.Particles}, {@link xpbdcloth.engine.Particle}: particle state (flat arrays) and its object view.</li>
 *   <li>{@link xpbdcloth.engine.Constraint}: both formulations in one place, PBD (k, Müller's k') and XPBD
 *       (α, λ): Δλ; its objects are views of one constraint of a block.</li>
 *   <li>{@link xpbdcloth.engine.ConstraintBlock}: one kind and family of constraints in flat arrays (indices,
 *       rest values, λ, material); each kind's maths (C, ∇C, projection) written once, in its block, and
 *       called by every solver: {@link xpbdcloth.engine.DistanceBlock} (|x_a − x_b| − L: structural edges,
 *       rope links), {@link xpbdcloth.engine.ShearBlock} (the angle between two edges at a vertex),
 *       {@link xpbdcloth.engine.BendBlock} (Kelager's triangle bending), {@link xpbdcloth.engine.AttachmentBlock}
 *       (a particle held at a moving target: the mouse grab); the views {@code DistanceConstraint} and so on.</li>
 *   <li>Contacts, one class per kind of surface, named …Contact: {@link xpbdcloth.engine.SphereContact},
 *       {@code PlaneContact}, {@code ShapeContact} (boxes and capsules): each one's C, ∇C and projection, which
 *       the transient contacts of {@code ContactSet} use, with the one Coulomb friction law of
 *       {@code CoulombFriction}; the surfaces themselves ({@link xpbdcloth.engine.Sphere}, {@link xpbdcloth.engine.Plane},
 *       {@link xpbdcloth.engine.RigidCollider}, {@link xpbdcloth.engine.MeshCollider}) are each a
 *       {@link xpbdcloth.engine.Collider}, which finds and projects its own contacts.</li>
 *   <li>{@link xpbdcloth.engine.Simulation}: the step, stage by stage ({@link xpbdcloth.engine.Stage}): predict,
 *       kinematics, collide (transient contacts, {@code ContactSet}), solve ({@code SolveStage}: sequential,
 *       parallel coloured or global, over a {@code SweepOrder} of blocks, chosen by {@code SolveStages}), update
 *       velocities, velocity pass; its constraints in a {@code ConstraintSet}, what a step cost in its
 *       {@link xpbdcloth.engine.StepProfile}. The global solver's linear algebra is in {@code xpbdcloth.linalg}.</li>
 *   <li>{@link xpbdcloth.engine.SolverSettings}, {@link xpbdcloth.engine.ConstraintMode}: parameters and units.</li>
 *   <li>{@link xpbdcloth.engine.MeshClothBuilder}, {@link xpbdcloth.engine.ClothBuilder}, {@link xpbdcloth.engine.Cloth}:
 *       cloths from any mesh ({@code xpbdcloth.mesh}), grid cloths and ropes.</li>
 *   <li>{@link xpbdcloth.engine.Sphere}, {@link xpbdcloth.engine.SpherePath}: kinematic spheres.</li>
 *   <li>{@link xpbdcloth.engine.Wind}, {@link xpbdcloth.engine.ExternalForce}, {@link xpbdcloth.engine.Kinematics}: forces and scripts.</li>
 *   <li>{@link xpbdcloth.engine.Metrics}: energies, momentum, strain; {@link xpbdcloth.engine.Check}: validation.</li>
 * </ul>
 */
package xpbdcloth.engine;
