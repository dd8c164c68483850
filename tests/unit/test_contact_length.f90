!> contact_kinematics' length2 (edge lengths and corner-corner distances of
!> the contact geometry, inlined into the contact loops) gives the same bits
!> as the C library's hypot, which the geometry used before (issue 23: the
!> rigid cycle's results must not change). Reference: hypot itself, no
!> tolerance. Pairs: random coordinate differences of unit size, near the
!> axes and the diagonal (lattice edges), across the exponent range down to
!> subnormals and up to near overflow, and special values (a NaN is not
!> tried: the Debug build traps it at the comparison, as it would trap where
!> a NaN position was made). The random pairs come from a fixed seed, so a
!> failure repeats; a sweep of the shorter side across the library's scaling
!> threshold (2**-459) and the pair that found it (a shorter side of 2.7e-154
!> was given the unscaled correction, one ulp off) are checked as well.
program test_contact_length
   use core_kinds, only: wp
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
   use contact_kinematics, only: length2
   use testing, only: check, testing_finish, testing_fixed_seed
   implicit none
   integer :: i, k, nbad
   real(wp) :: r(4), x, y, inf
   integer, parameter :: n = 3000000
   call testing_fixed_seed()
   nbad = 0
   do i = 1, n
      call random_number(r)
      k = mod(i, 5)
      select case (k)
      case (0)
         x = 2.0_wp*r(1) - 1.0_wp
         y = 2.0_wp*r(2) - 1.0_wp
      case (1)
         x = 1.0_wp + 1.0e-6_wp*(r(1) - 0.5_wp)
         y = 1.0e-5_wp*(r(2) - 0.5_wp)
      case (2)
         x = 0.01_wp*r(1)
         y = -x*(1.0_wp + 1.0e-3_wp*(r(2) - 0.5_wp))
      case (3)
         x = sign(scale(r(1), int(r(3)*200.0_wp) - 100), r(4) - 0.5_wp)
         y = scale(r(2), int(r(4)*200.0_wp) - 100)
      case default
         ! scale, not 2.0**k: 2.0**(-k) is 1 / 2**k, which overflows (a trap
         ! in the Debug build) for k > 1023
         x = scale(r(1), int(r(3)*2040.0_wp) - 1070)
         y = -scale(r(2), int(r(4)*2040.0_wp) - 1070)
      end select
      if (.not. same(length2(x, y), hypot(x, y))) nbad = nbad + 1
      if (.not. same(length2(y, x), hypot(y, x))) nbad = nbad + 1
   end do
   call check(nbad == 0, 'length2 is hypot to the last bit on 6 million random pairs')
   ! the shorter side from 2**-530 to 2**-440, the longer side 1 to 64 times it
   nbad = 0
   do i = 1, 400000
      call random_number(r)
      y = scale(1.0_wp + r(1), -530 + int(r(2)*90.0_wp))
      x = y*(1.0_wp + 63.0_wp*r(3))
      if (.not. same(length2(x, y), hypot(x, y))) nbad = nbad + 1
      if (.not. same(length2(-y, x), hypot(-y, x))) nbad = nbad + 1
   end do
   call check(nbad == 0, 'length2 is hypot across the scaling threshold of the shorter side')
   x = transfer(int(z'20353013E067D9F0', int64), 1.0_wp)
   y = transfer(int(z'A00CB9C868C45C1D', int64), 1.0_wp)
   call check(same(length2(x, y), hypot(x, y)), 'length2(1.58e-153, -2.68e-154) as hypot')
   inf = ieee_value(1.0_wp, ieee_positive_inf)
   nbad = 0
   do i = -1074, 1023, 7
      x = scale(1.0_wp, i)
      do k = -1074, 1023, 11
         y = scale(1.0_wp, k)
         if (.not. same(length2(x, y), hypot(x, y))) nbad = nbad + 1
         if (.not. same(length2(-x, 0.0_wp), hypot(-x, 0.0_wp))) nbad = nbad + 1
         if (.not. same(length2(x*1.3_wp, y*0.7_wp), hypot(x*1.3_wp, y*0.7_wp))) nbad = nbad + 1
      end do
   end do
   call check(nbad == 0, 'length2 is hypot on powers of two, their multiples and (x, 0)')
   call check(length2(0.0_wp, 0.0_wp) == 0.0_wp, 'length2(0, 0) = 0')
   call check(length2(-3.0_wp, 4.0_wp) == 5.0_wp, 'length2(-3, 4) = 5')
   x = 0.6_wp*huge(1.0_wp)
   y = 0.7_wp*huge(1.0_wp)
   call check(same(length2(x, y), hypot(x, y)), 'length2 near overflow (scaled) as hypot')
   call check(length2(tiny(1.0_wp)*1.0e-10_wp, 0.0_wp) == tiny(1.0_wp)*1.0e-10_wp, &
              'length2 of a subnormal')
   call check(length2(inf, 1.0_wp) == inf, 'length2(inf, 1) = inf')
   call testing_finish()
contains
   logical function same(a, b)
      real(wp), intent(in) :: a, b
      same = a == b .or. (a /= a .and. b /= b)
   end function same
end program test_contact_length
