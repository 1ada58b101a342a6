// TEMPORARY until the F77 integrator branch lands.
extern "C" __attribute__((weak)) int np_f77_bsint_smooth_bar(int, double, double*, int, const double*, double*, double,
                                                             const double*, double, double, int, int, int,
                                                             const double*, int*) {
  return 1;
}
