!> nanopush_assemble through `use nanopush` (and so the C API's nanopush_assemble): two nanorods
!> into a two-slot pattern, each to the other's side, equal to `nanopush assemble`'s
!> assembly.csv row for row (given); bad shapes and counts as stat + errmsg, nothing written
!> (slot_of and final of another size than n included).
!> Usage: capi_test_assemble_fortran SCENE.toml ASSEMBLY.csv
program test_fortran_assemble
  use nanopush
  use test_support, only: check, finish, open_csv
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: pushes(:, :)
  real(dp) :: final(3, 2), row(11)
  real(dp), parameter :: objects(3, 2) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 100e-9_dp, 0.0_dp, 0.0_dp], [3, 2])
  real(dp), parameter :: slots(3, 2) = reshape([110e-9_dp, 20e-9_dp, 0.1_dp, 10e-9_dp, 20e-9_dp, 0.1_dp], [3, 2])
  real(dp), parameter :: tol(2) = [2e-9_dp, 0.02_dp]
  real(dp) :: big_final(3, 5)
  integer :: slot_of(2), big_slot_of(5), small_slot_of(1), stat, k, u, ios
  logical :: assembled
  character(len=:), allocatable :: msg
  character(len=4096) :: arg

  if (command_argument_count() /= 2) error stop "usage: capi_test_assemble_fortran SCENE.toml ASSEMBLY.csv"
  call get_command_argument(1, arg)
  call nanopush_load_scene(scene, trim(arg))

  call nanopush_assemble(scene, objects, slots, pushes, slot_of=slot_of, final=final, assembled=assembled, &
                         tolerance=tol, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_OK, "assemble: stat " // msg)
  call check(assembled, "assemble: assembled")
  call check(all(slot_of == [2, 1]), "assemble: each rod to the other's side")
  call check(size(pushes, 2) == 10 .and. size(pushes, 1) >= 2, "assemble: pushes(k, 10)")
  do k = 1, 2
    call check(hypot(final(1, k) - slots(1, slot_of(k)), final(2, k) - slots(2, slot_of(k))) <= tol(1), &
               "assemble: a rod within its slot")
  end do
  ! The command line's assembly.csv (bar, slot, push, start_x, ..., theta_end), bit for bit.
  call get_command_argument(2, arg)
  u = open_csv(trim(arg), "bar,slot,push,start_x,start_y,direction,speed,travel,x_end,y_end,theta_end", &
               "assemble: assembly.csv's header")
  k = 0
  do
    read (u, *, iostat=ios) row
    if (ios /= 0) exit
    k = k + 1
    if (k <= size(pushes, 1)) call check(all(row([1, 2]) == pushes(k, 1:2)) .and. all(row(4:11) == pushes(k, 3:10)), &
                                         "assemble: a row of assembly.csv")
  end do
  close (u)
  call check(k == size(pushes, 1), "assemble: as many rows as assembly.csv")

  ! slot_of and final of another size than n = 2: refused before anything runs, nothing read or
  ! written past either array (it was an out-of-bounds read when larger, a silent cut when smaller).
  big_slot_of = -99
  big_final = -99
  call nanopush_assemble(scene, objects, slots, pushes, slot_of=big_slot_of, final=final, tolerance=tol, &
                         stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. msg == "size(slot_of) = 5: must be n = 2 (one slot per bar)" .and. &
             size(pushes, 1) == 0 .and. all(big_slot_of == -99), "slot_of larger than n: " // msg)
  call nanopush_assemble(scene, objects, slots, pushes, slot_of=small_slot_of, tolerance=tol, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "size(slot_of) = 1: must be n = 2") == 1, &
             "slot_of smaller than n: " // msg)
  call nanopush_assemble(scene, objects, slots, pushes, slot_of=slot_of, final=big_final, tolerance=tol, &
                         stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. &
             msg == "shape(final) = (3, 5): must be (3, n) = (3, 2) (x, y, theta of each bar)" .and. &
             all(big_final == -99), "final larger than n: " // msg)
  call nanopush_assemble(scene, objects, slots, pushes, final=big_final(:, 1:1), tolerance=tol, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "shape(final) = (3, 1): must be (3, n) = (3, 2)") == 1, &
             "final smaller than n: " // msg)
  call nanopush_assemble(scene, objects, slots, pushes, final=big_final(1:2, 1:2), tolerance=tol, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "shape(final) = (2, 2)") == 1, "final of 2 rows: " // msg)

  call nanopush_assemble(scene, objects, slots(:, 1:1), pushes, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "same n") > 0 .and. size(pushes, 1) == 0, "bad shape: " // msg)
  call nanopush_assemble(scene, objects, objects, pushes, max_pushes=0, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "max_pushes") > 0, "bad max_pushes: " // msg)
  ! The library's --gap named as the argument, gap.
  call nanopush_assemble(scene, objects, slots, pushes, gap=-1.0_dp, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. msg == "gap = -1: must be >= 0 (m)", "bad gap: " // msg)

  call nanopush_destroy(scene)
  if (allocated(pushes)) deallocate(pushes)
  if (allocated(msg)) deallocate(msg)
  call finish("test_fortran_assemble")
end program test_fortran_assemble
