/**
 * Sparse and banded linear algebra, knowing nothing of cloth: {@link xpbdcloth.linalg.SparseMatrix}
 * (compressed rows, the pattern fixed and the values refilled in place), the
 * {@link xpbdcloth.linalg.AggregationMultigrid} V-cycle and its line smoother
 * {@link xpbdcloth.linalg.ChainSmoother} (the global solver's preconditioner), and
 * {@link xpbdcloth.linalg.BandedMatrix} (the banded Cholesky of the fitting's Newton steps). It imports
 * nothing of the project; the engine and the fitting stand on it.
 */
package xpbdcloth.linalg;
