!> Minimal assertion helpers for udec unit tests. Each check prints a line on
!> failure and counts it; `testing_finish` stops with status 1 if any failed.
module testing
   use core_kinds, only: wp, i1
   implicit none
   private
   public :: check, check_close, check_equal, check_string, testing_finish, delete_file
   public :: testing_fixed_seed

   integer, save :: failures = 0, checks = 0

   interface check_equal
      module procedure check_equal_int, check_equal_code
   end interface check_equal

contains

   !> Seeds the intrinsic random_number from a fixed sequence, so that a test
   !> drawing random cases draws the same ones in every run and a failure
   !> repeats (gfortran otherwise seeds it from the system at each start).
   subroutine testing_fixed_seed()
      integer :: i, n
      integer, allocatable :: seed(:)
      call random_seed(size=n)
      allocate (seed(n))
      seed = [(104729*i + 17, i = 1, n)]
      call random_seed(put=seed)
   end subroutine testing_fixed_seed

   subroutine check(condition, label)
      logical, intent(in) :: condition
      character(len=*), intent(in) :: label
      checks = checks + 1
      if (.not. condition) then
         failures = failures + 1
         write (*, '(a)') 'FAIL: '//label
      end if
   end subroutine check

   !> |actual - expected| <= tol * max(1, |expected|)
   subroutine check_close(actual, expected, tol, label)
      real(wp), intent(in) :: actual, expected, tol
      character(len=*), intent(in) :: label
      checks = checks + 1
      if (.not. abs(actual - expected) <= tol*max(1.0_wp, abs(expected))) then
         failures = failures + 1
         write (*, '(a,2(a,es24.16))') 'FAIL: '//label, ' actual=', actual, ' expected=', expected
      end if
   end subroutine check_close

   subroutine check_equal_int(actual, expected, label)
      integer, intent(in) :: actual, expected
      character(len=*), intent(in) :: label
      checks = checks + 1
      if (actual /= expected) then
         failures = failures + 1
         write (*, '(a,2(a,i0))') 'FAIL: '//label, ' actual=', actual, ' expected=', expected
      end if
   end subroutine check_equal_int

   !> One-byte codes (contact state bits).
   subroutine check_equal_code(actual, expected, label)
      integer(i1), intent(in) :: actual, expected
      character(len=*), intent(in) :: label
      call check_equal_int(int(actual), int(expected), label)
   end subroutine check_equal_code

   subroutine check_string(actual, expected, label)
      character(len=*), intent(in) :: actual, expected
      character(len=*), intent(in) :: label
      checks = checks + 1
      if (actual /= expected) then
         failures = failures + 1
         write (*, '(a)') 'FAIL: '//label//' actual="'//actual//'" expected="'//expected//'"'
      end if
   end subroutine check_string

   subroutine testing_finish()
      write (*, '(i0,a,i0,a)') checks, ' checks, ', failures, ' failures'
      if (failures > 0) error stop 1
   end subroutine testing_finish

   !> Removes the file at `path` if it exists (a test's output from an earlier run).
   subroutine delete_file(path)
      character(len=*), intent(in) :: path
      integer :: u, ios
      open (newunit=u, file=path, status='old', iostat=ios)
      if (ios == 0) close (u, status='delete')
   end subroutine delete_file

end module testing
