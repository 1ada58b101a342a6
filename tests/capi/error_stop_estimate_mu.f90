!> Without `stat`, bad input to nanopush_estimate_mu_from_icor stops the program with the library's
!> message naming the quantity (`error stop`, non-zero exit). Run by two CTests: message and exit.
program error_stop_estimate_mu
  use nanopush
  implicit none
  real(dp) :: mu, sigma
  call nanopush_estimate_mu_from_icor(nanopush_icor_nanorod(), 1e-6_dp, 0.0_dp, 0.0_dp, 0.0_dp, mu, sigma)
  print '(a)', "not reached: the call above must stop the program"
end program error_stop_estimate_mu
