!> What every Fortran test program shares (tests/CMakeLists.txt links it into each):
!> check() counts and reports failed checks, finish() ends the program with a nonzero status
!> when any failed, and the thresholds below name the agreement the tests ask for; same()
!> checks two doubles are the same (NaN equals NaN), argument() reads a command-line argument,
!> open_csv() opens a CSV and checks its header, field() and fields() read the comma-separated
!> fields of a CSV line (no quoting), and compare_with_run() holds a trajectory to the CSV
!> `nanopush run` wrote, number for number.
module test_support
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none
  private
  public :: check, finish, failures, checks, tol_agree, tol_round_trip, same, argument, open_csv, field, &
            fields, compare_with_run

  !> Two implementations of the same double-precision computation (C++ against F77, Brent
  !> against LAPACK, one integration through two front ends): the arithmetic is reordered, so
  !> a few thousand ulps of slack, and nothing a wrong formula could hide in.
  real(real64), parameter :: tol_agree = 1e-12_real64
  !> A value through a closed form and back through its inverse (a friction coefficient from
  !> the forces it gave): a few hundred ulps, two evaluations' rounding.
  real(real64), parameter :: tol_round_trip = 1e-13_real64

  integer, save :: failures = 0  !< checks that failed so far
  integer, save :: checks = 0    !< checks made so far

contains

  !> Counts the check; when `ok` is false, counts a failure and prints "FAIL: what".
  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. ok) then
      failures = failures + 1
      print '(2a)', "FAIL: ", what
    end if
  end subroutine check

  !> Prints "N checks, M failures" and, when any check failed, stops with a nonzero status
  !> naming the program.
  subroutine finish(program_name)
    character(len=*), intent(in) :: program_name
    print '(i0,a,i0,a)', checks, " checks, ", failures, " failures"
    if (failures > 0) error stop program_name // ": failures above"
  end subroutine finish

  !> Checks that `got` is the same double as `want` (or both NaN); prints both when not.
  subroutine same(got, want, what)
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    real(real64), intent(in) :: got, want
    character(len=*), intent(in) :: what
    logical :: ok
    ok = got == want .or. (ieee_is_nan(got) .and. ieee_is_nan(want))
    if (.not. ok) print '(a,": got ",es25.17," want ",es25.17)', what, got, want
    call check(ok, what)
  end subroutine same

  !> The i-th command-line argument, as long as it is.
  function argument(i) result(a)
    integer, intent(in) :: i
    character(len=:), allocatable :: a
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: a)
    call get_command_argument(i, a)
  end function argument

  !> Opens the CSV at `path` for reading, checks (as `what`) that its header line is `header`,
  !> and returns the unit, at the first data row.
  function open_csv(path, header, what) result(unit)
    character(len=*), intent(in) :: path, header, what
    integer :: unit
    character(len=4096) :: line
    open (newunit=unit, file=path, status="old", action="read")
    read (unit, '(a)') line
    call check(trim(line) == header, what)
  end function open_csv

  !> The i-th comma-separated field of a CSV line (no quoting in these files); "" past the last.
  function field(line, i) result(f)
    character(len=*), intent(in) :: line
    integer, intent(in) :: i
    character(len=:), allocatable :: f
    integer :: k, start, comma
    start = 1
    do k = 1, i - 1
      comma = index(line(start:), ",")
      if (comma == 0) then
        f = ""
        return
      end if
      start = start + comma
    end do
    comma = index(line(start:), ",")
    if (comma == 0) then
      f = trim(line(start:))
    else
      f = line(start:start + comma - 2)
    end if
  end function field

  !> Fields first, first + 1, ... (first defaults to 1) as numbers, size(v) of them; empty or
  !> non-numeric fields (a branch that does not exist, a label) become NaN.
  subroutine fields(line, v, first)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    character(len=*), intent(in) :: line
    real(real64), intent(out) :: v(:)
    integer, intent(in), optional :: first
    integer :: i, ios, offset
    character(len=:), allocatable :: f
    offset = 0
    if (present(first)) offset = first - 1
    do i = 1, size(v)
      f = field(line, i + offset)
      v(i) = ieee_value(0.0_real64, ieee_quiet_nan)
      if (len_trim(f) == 0) cycle
      read (f, *, iostat=ios) v(i)
      if (ios /= 0) v(i) = ieee_value(0.0_real64, ieee_quiet_nan)
    end do
  end subroutine fields

  !> Compares the trajectory traj(10, rows) with the CSV `nanopush run --out` wrote at `path`
  !> (17 significant digits, so equal doubles read back equal): prints the rows read, the rows
  !> that differ and the largest difference, and error-stops, naming `program_name`, when the
  !> header, the row count or any number differs.
  subroutine compare_with_run(traj, path, program_name)
    real(real64), intent(in) :: traj(:, :)
    character(len=*), intent(in) :: path, program_name
    character(len=512) :: header
    real(real64) :: row(size(traj, 1)), worst
    integer :: unit, ios, nref, differ
    open (newunit=unit, file=path, status="old", action="read")
    read (unit, '(a)') header
    if (trim(header) /= "t,x,y,theta,vx,vy,omega,fx,fy,mf") error stop program_name // ": unexpected CSV header"
    nref = 0
    differ = 0
    worst = 0
    do
      read (unit, *, iostat=ios) row
      if (ios /= 0) exit
      nref = nref + 1
      if (nref > size(traj, 2)) exit
      if (any(row /= traj(:, nref))) differ = differ + 1
      worst = max(worst, maxval(abs(row - traj(:, nref))))
    end do
    close (unit)
    print '(a,i0,a,i0,a,es10.3)', "reference rows ", nref, ", rows that differ ", differ, ", largest |difference| ", worst
    if (nref /= size(traj, 2)) error stop program_name // ": row count differs from nanopush run"
    if (differ /= 0) error stop program_name // ": numbers differ from nanopush run"
  end subroutine compare_with_run

end module test_support
