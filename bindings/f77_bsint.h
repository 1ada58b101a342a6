/* PLACEHOLDER, replaced by the F77 bridge branch. */
#ifndef NANOPUSH_F77_BSINT_H
#define NANOPUSH_F77_BSINT_H
#ifdef __cplusplus
extern "C" {
#endif
int np_f77_bsint_smooth_bar(int n, double t0, double* y, int nout, const double* tout, double* yout, double rtol,
                            const double* atol, double h0, double hmax, int kmax, int iextr, int maxstp,
                            const double* params, int* nstat);
#ifdef __cplusplus
}
#endif
#endif
