!> Bridge to the FORTRAN 77 rough-surface nanobar (fortran/rgbar.f) integrated by the F77
!> Bulirsch-Stoer driver (fortran/bsint.f). C prototypes, units and shapes: f77_rough.h.
module nanopush_f77_rough
  use nanopush_f77_interfaces, only: bsint, rgbar
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  implicit none
  private
  public :: np_f77_rough_bar_rhs_law, np_f77_bsint_rough_bar_law


contains

  !> RGBAR's IPAR from a law code: 0 thesis; 1 + i the printed law under reading i (0..15: bit 0
  !> corrects F1, bit 1 F3, bit 2 takes cubes in C4, bit 3 prints eq 3.50; nanopush::printed_reading).
  pure function law_ipar(law) result(ipar)
    integer(c_int), intent(in) :: law
    integer :: ipar(5), i
    ipar = 0
    if (law < 1) return
    i = int(law) - 1
    ipar(1) = 1
    ipar(2) = 1 - ibits(i, 0, 1)
    ipar(3) = 1 - ibits(i, 1, 1)
    ipar(4) = 1 - ibits(i, 2, 1)
    ipar(5) = ibits(i, 3, 1)
  end function law_ipar

  !> One evaluation of the F77 rough-bar RHS (8 states, 12 parameters) under a friction law code
  !> (law_ipar); returns its IERR.
  integer(c_int) function np_f77_rough_bar_rhs_law(t, y, dydt, params, law) bind(C, name="np_f77_rough_bar_rhs_law")
    real(c_double), value, intent(in) :: t
    real(c_double), intent(in) :: y(8)
    real(c_double), intent(out) :: dydt(8)
    real(c_double), intent(in) :: params(12)
    integer(c_int), value, intent(in) :: law
    integer :: ipar(5), ierr
    ipar = law_ipar(law)
    ierr = 0
    call rgbar(8, t, y, dydt, params, ipar, ierr)
    np_f77_rough_bar_rhs_law = int(ierr, c_int)
  end function np_f77_rough_bar_rhs_law

  !> Integrate the F77 rough-bar RHS with BSINT under a friction law code (law_ipar); arguments
  !> as np_f77_bsint_smooth_bar; returns 1 for a bad n or code.
  integer(c_int) function np_f77_bsint_rough_bar_law(n, t0, y, nout, tout, yout, rtol, atol, h0, &
                                                     hmax, kmax, iextr, maxstp, params, law, nstat) &
      bind(C, name="np_f77_bsint_rough_bar_law")
    integer(c_int), value, intent(in) :: n, nout, kmax, iextr, maxstp, law
    real(c_double), value, intent(in) :: t0, rtol, h0, hmax
    real(c_double), intent(inout) :: y(*)
    real(c_double), intent(in) :: tout(*), atol(*)
    real(c_double), intent(inout) :: yout(*)
    real(c_double), intent(in) :: params(12)
    integer(c_int), intent(out) :: nstat(3)
    integer :: ipar(5), ist(3), ierr
    nstat = 0_c_int
    if (n /= 8 .or. law < 0 .or. law > 16) then
      np_f77_bsint_rough_bar_law = 1_c_int
      return
    end if
    ipar = law_ipar(law)
    call bsint(rgbar, int(n), t0, y, int(nout), tout, yout, rtol, atol, h0, hmax, int(kmax), &
               int(iextr), int(maxstp), params, ipar, ist, ierr)
    nstat = int(ist, c_int)
    np_f77_bsint_rough_bar_law = int(ierr, c_int)
  end function np_f77_bsint_rough_bar_law

end module nanopush_f77_rough
