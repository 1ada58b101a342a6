!> Bridge to the FORTRAN 77 Bulirsch-Stoer integrator (fortran/bsint.f).
!>
!> np_f77_bsint integrates a right-hand side written in C or C++ (a C function pointer plus an
!> opaque udata pointer); np_f77_bsint_smooth_bar integrates the F77 smooth-nanobar RHS
!> (fortran/smbar.f). C prototypes, units and shapes: fortran/bridge/f77_bsint.h.
!>
!> Re-entrancy: the C function pointer and udata travel to the trampoline inside the IPAR
!> integer array that BSINT hands unchanged to its EXTERNAL derivative routine (bit copies made
!> with transfer()). There is no global or saved state, so several integrations may run
!> interleaved (a callback may itself start another integration) or on several threads.
module nanopush_f77_bsint
  use nanopush_f77_interfaces, only: bsint, smbar, smbarp
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_funptr, c_intptr_t, &
                                         c_f_procpointer
  implicit none
  private
  public :: np_f77_bsint, np_f77_bsint_fcn, np_f77_bsint_smooth_bar

  !> Default INTEGER words holding one C address (c_intptr_t is a whole number of them on
  !> every platform gfortran supports: 64/32 or 32/32 bits).
  integer, parameter :: nw = storage_size(0_c_intptr_t) / storage_size(0)

  !> The C right-hand side: int rhs(int n, double t, const double* y, double* dydt, void* udata).
  abstract interface
    integer(c_int) function c_rhs(n, t, y, dydt, udata) bind(C)
      import :: c_int, c_double, c_ptr
      integer(c_int), value, intent(in) :: n
      real(c_double), value, intent(in) :: t
      real(c_double), intent(in) :: y(*)
      real(c_double), intent(out) :: dydt(*)
      type(c_ptr), value, intent(in) :: udata
    end function c_rhs
    !> A derivative routine in BSINT's own calling convention (every argument by reference),
    !> written in C or C++: void fcn(const int* n, const double* t, const double* y,
    !> double* dydt, const double* rpar, int* ipar, int* ierr).
    subroutine c_fcn(n, t, y, dydt, rpar, ipar, ierr) bind(C)
      import :: c_int, c_double
      integer(c_int), intent(in) :: n
      real(c_double), intent(in) :: t
      real(c_double), intent(in) :: y(n)
      real(c_double), intent(out) :: dydt(n)
      real(c_double), intent(in) :: rpar(*)
      integer(c_int), intent(inout) :: ipar(*)
      integer(c_int), intent(inout) :: ierr
    end subroutine c_fcn
  end interface


contains

  !> The EXTERNAL derivative routine BSINT calls: unpacks the C function pointer (ipar(1:nw))
  !> and udata (ipar(nw+1:2*nw)) and calls the C right-hand side. ierr = its return value.
  subroutine bsint_trampoline(n, t, y, dydt, rpar, ipar, ierr)
    integer, intent(in) :: n
    double precision, intent(in) :: t
    double precision, intent(in) :: y(n)
    double precision, intent(out) :: dydt(n)
    double precision, intent(in) :: rpar(*)
    integer, intent(inout) :: ipar(*)
    integer, intent(inout) :: ierr
    type(c_funptr) :: fptr
    type(c_ptr) :: udata
    procedure(c_rhs), pointer :: f
    fptr = transfer(ipar(1:nw), fptr)
    udata = transfer(ipar(nw + 1:2 * nw), udata)
    call c_f_procpointer(fptr, f)
    ierr = int(f(int(n, c_int), real(t, c_double), y, dydt, udata))
  end subroutine bsint_trampoline

  !> Integrate y' = rhs(t, y) from t0 through the output times tout(1:nout) with the F77
  !> Bulirsch-Stoer engine. Arguments and status: see fortran/bridge/f77_bsint.h.
  integer(c_int) function np_f77_bsint(n, t0, y, nout, tout, yout, rtol, atol, h0, hmax, kmax, &
                                       iextr, maxstp, rhs, udata, nstat) &
      bind(C, name="np_f77_bsint")
    integer(c_int), value, intent(in) :: n, nout, kmax, iextr, maxstp
    real(c_double), value, intent(in) :: t0, rtol, h0, hmax
    real(c_double), intent(inout) :: y(*)
    real(c_double), intent(in) :: tout(*), atol(*)
    real(c_double), intent(inout) :: yout(*)
    type(c_funptr), value, intent(in) :: rhs
    type(c_ptr), value, intent(in) :: udata
    integer(c_int), intent(out) :: nstat(3)
    integer :: ipar(2 * nw), ist(3), ierr
    double precision :: rpar(1)
    rpar(1) = 0d0
    ipar(1:nw) = transfer(rhs, ipar(1:nw))
    ipar(nw + 1:2 * nw) = transfer(udata, ipar(1:nw))
    ! yout is passed as a flat array: BSINT addresses it as yout(n, nout) (column-major,
    ! component fastest), which is the C layout yout[i + n*k].
    call bsint(bsint_trampoline, int(n), t0, y, int(nout), tout, yout, rtol, atol, h0, hmax, &
               int(kmax), int(iextr), int(maxstp), rpar, ipar, ist, ierr)
    nstat = int(ist, c_int)
    np_f77_bsint = int(ierr, c_int)
  end function np_f77_bsint

  !> As np_f77_bsint, with the derivative routine handed to BSINT itself (F77 calling
  !> convention, fortran/bridge/f77_bsint.h np_f77_bsint_fcn): no trampoline and one call per RHS
  !> evaluation instead of three. udata travels in ipar(1:nw), which fcn receives.
  integer(c_int) function np_f77_bsint_fcn(n, t0, y, nout, tout, yout, rtol, atol, h0, hmax, kmax, &
                                           iextr, maxstp, fcn, udata, nstat) &
      bind(C, name="np_f77_bsint_fcn")
    integer(c_int), value, intent(in) :: n, nout, kmax, iextr, maxstp
    real(c_double), value, intent(in) :: t0, rtol, h0, hmax
    real(c_double), intent(inout) :: y(*)
    real(c_double), intent(in) :: tout(*), atol(*)
    real(c_double), intent(inout) :: yout(*)
    type(c_funptr), value, intent(in) :: fcn
    type(c_ptr), value, intent(in) :: udata
    integer(c_int), intent(out) :: nstat(3)
    integer :: ipar(nw), ist(3), ierr
    double precision :: rpar(1)
    procedure(c_fcn), pointer :: f
    rpar(1) = 0d0
    ipar(1:nw) = transfer(udata, ipar(1:nw))
    call c_f_procpointer(fcn, f)
    call bsint(f, int(n), t0, y, int(nout), tout, yout, rtol, atol, h0, hmax, &
               int(kmax), int(iextr), int(maxstp), rpar, ipar, ist, ierr)
    nstat = int(ist, c_int)
    np_f77_bsint_fcn = int(ierr, c_int)
  end function np_f77_bsint_fcn

  !> Integrate the F77 smooth-nanobar RHS (n must be 6). params(6) = (m [kg], I [kg m^2],
  !> F [N], beta [rad], pbx [m], pby [m]). Other arguments as np_f77_bsint.
  integer(c_int) function np_f77_bsint_smooth_bar(n, t0, y, nout, tout, yout, rtol, atol, h0, &
                                                  hmax, kmax, iextr, maxstp, params, nstat) &
      bind(C, name="np_f77_bsint_smooth_bar")
    integer(c_int), value, intent(in) :: n, nout, kmax, iextr, maxstp
    real(c_double), value, intent(in) :: t0, rtol, h0, hmax
    real(c_double), intent(inout) :: y(*)
    real(c_double), intent(in) :: tout(*), atol(*)
    real(c_double), intent(inout) :: yout(*)
    real(c_double), intent(in) :: params(6)
    integer(c_int), intent(out) :: nstat(3)
    integer :: ipar(1), ist(3), ierr
    double precision :: rpar(8)
    nstat = 0_c_int
    if (n /= 6) then
      np_f77_bsint_smooth_bar = 1_c_int
      return
    end if
    ! smbar's rpar: the six parameters, then the push force (rpar(7:8)) that smbarp computes
    ! once for the whole integration.
    rpar(1:6) = params
    call smbarp(rpar)
    ipar(1) = 0
    call bsint(smbar, int(n), t0, y, int(nout), tout, yout, rtol, atol, h0, hmax, int(kmax), &
               int(iextr), int(maxstp), rpar, ipar, ist, ierr)
    nstat = int(ist, c_int)
    np_f77_bsint_smooth_bar = int(ierr, c_int)
  end function np_f77_bsint_smooth_bar

end module nanopush_f77_bsint
