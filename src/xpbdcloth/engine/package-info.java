/**
 * The engine: plain Java, no Processing. SI units throughout (m, s, kg, N).
 * <ul>
 *   <li>{@link xpbdcloth.engine.Particles}, {@link xpbdcloth.engine.Particle}: particle state (flat arrays) and its object view.</li>
 *   <li>{@link xpbdcloth.engine.Constraint}: the base with both projections, PBD (k, Müller's k') and XPBD (α, λ).</li>
 *   <li>{@link xpbdcloth.engine.DistanceConstraint}: |x_a − x_b| − L (structural edges, rope links).</li>
 *   <li>{@link xpbdcloth.engine.ShearConstraint}: the angle between two edges at a vertex.</li>
 *   <li>{@link xpbdcloth.engine.BendConstraint}: Kelager's triangle bending (vertex to centroid distance).</li>
 *   <li>{@link xpbdcloth.engine.SphereCollisionConstraint}: sphere contact with Coulomb friction and ω × r (its
 *       projection is the one transient contacts use).</li>
 *   <li>{@link xpbdcloth.engine.AttachmentConstraint}: a particle held at a moving target (mouse grab).</li>
 *   <li>{@link xpbdcloth.engine.Simulation}: the step, stage by stage ({@link xpbdcloth.engine.Stage}): predict,
 *       kinematics, collide (transient contacts, {@code ContactSet}), solve ({@code SolveStage}: sequential,
 *       parallel coloured or global), update velocities.</li>
 *   <li>{@link xpbdcloth.engine.SolverSettings}, {@link xpbdcloth.engine.ConstraintMode}: parameters and units.</li>
 *   <li>{@link xpbdcloth.engine.MeshClothBuilder}, {@link xpbdcloth.engine.ClothBuilder}, {@link xpbdcloth.engine.Cloth}:
 *       cloths from any mesh ({@code xpbdcloth.mesh}), grid cloths and ropes.</li>
 *   <li>{@link xpbdcloth.engine.Sphere}, {@link xpbdcloth.engine.SpherePath}: kinematic spheres.</li>
 *   <li>{@link xpbdcloth.engine.Wind}, {@link xpbdcloth.engine.ExternalForce}, {@link xpbdcloth.engine.Kinematics}: forces and scripts.</li>
 *   <li>{@link xpbdcloth.engine.Metrics}: energies, momentum, strain; {@link xpbdcloth.engine.Check}: validation.</li>
 * </ul>
 */
package xpbdcloth.engine;
