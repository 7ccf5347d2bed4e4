/*
 * brachistochrone.h: the C interface of the brachistochrone library (Fortran, bind(C);
 * module brachistochrone_c_api in src/c_api/). Link with -lbrachistochrone and the
 * GNU Fortran runtime: -lgfortran -lquadmath -lgomp -lm (pkg-config brachistochrone).
 *
 * Units (Tee 1998): the start A is at radius 1, angle 0, released from rest; |mu| = 1.
 * An endpoint B = (rho, psi): radius rho and angle psi (radians) from OA.
 *
 * force: "inverse_square" (0 < rho <= 1, the fast path), "power" (F = mu/r^n with
 * n = exponent, 1 < n <= 32), "logarithmic" (F = mu/r), "harmonic" (inside a uniform planet,
 * Saitoh), "repulsive" (F = -mu/r^2, rho >= 1; the least-time brachistochrone),
 * "uniform" (uniform gravity g = 1: rho and psi are then the Cartesian x >= 0 across
 * and y >= 0 down from A, and apse_radius is the cycloid's rolling-circle radius).
 * exponent is used by "power" only (pass 0 otherwise).
 *
 * Results: apse_radius = R-bar (the minimum radius of the curve), arclength = s and
 * time = t from A to B. A value that does not exist is NaN:
 *   - R-bar for radial fall (psi = 0) and for unbounded (repulsive) curves;
 *   - R-bar and s when B is inaccessible (status 1: t is then the greatest lower bound
 *     kappa(rho) of the time, never attained);
 *   - all three when the status is an error (bad input, unknown force, ...).
 * Any output pointer may be NULL: that output is not written.
 *
 * Status: 0 = solved; otherwise brachistochrone_status_message(status) says why
 * (for example 1: inaccessible, 2: rho out of range, 4: NaN or infinite input,
 * 14: unknown field name, 15: bad exponent). Unknown names and bad exponents return a
 * status; nothing aborts.
 *
 * Thread safety: every function may be called from several threads at once. A field
 * (the inverse-square model or a power law's rules: about 50 ms of CPU to build) is
 * built on the first call that names it (for "power": with that exponent), once, and
 * shared read-only afterwards; up to 16 fields are kept, a 17th distinct one is built
 * for its call only.
 */
#ifndef BRACHISTOCHRONE_H
#define BRACHISTOCHRONE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The status of a solved endpoint. */
#define BRACHISTOCHRONE_OK 0

/* Solve one endpoint in double precision (computed in quad precision, then rounded).
   Returns the status. */
int brachistochrone_solve(const char *force, double exponent, double rho, double psi,
                          double *apse_radius, double *arclength, double *time);

#if defined(__SIZEOF_FLOAT128__) || defined(BRACHISTOCHRONE_HAVE_FLOAT128)
/* The same with quad-precision (IEEE binary128) arguments and results: all 34 digits.
   NaN as above. */
int brachistochrone_solve_q(const char *force, __float128 exponent, __float128 rho,
                            __float128 psi, __float128 *apse_radius,
                            __float128 *arclength, __float128 *time);
#endif

/* Solve n endpoints rho[i], psi[i] in parallel (OpenMP threads inside; set
   OMP_NUM_THREADS to choose how many; the results do not depend on it). Writes
   apse_radius[i], arclength[i], time[i] (NaN as above) and status[i]; any of these
   arrays may be NULL. Returns the number of endpoints whose status is not 0 (at most
   INT_MAX), or -1 when n < 0 or rho or psi is NULL with n > 0. */
int brachistochrone_solve_many(const char *force, double exponent, long n,
                               const double *rho, const double *psi,
                               double *apse_radius, double *arclength, double *time,
                               int *status);

/* One sentence for a status code: a static NUL-terminated string (do not free it);
   "unknown status" for a number that is not a status code. */
const char *brachistochrone_status_message(int status);

/* 1 where the machine's x87 arithmetic is at its defaults (precision control at 64 bits,
   rounding to nearest), as the library's quad-precision arithmetic assumes; 0 where the
   program or a library changed them (gcc/gfortran -mpc64, fldcw, fesetround): the
   results would then be wrong (by up to 1e22 ulp at 53 bits). Check it once before
   solving. */
int brachistochrone_arithmetic_ok(void);

#ifdef __cplusplus
}
#endif

#endif /* BRACHISTOCHRONE_H */
