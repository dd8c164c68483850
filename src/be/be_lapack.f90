!> LAPACK behind explicit interfaces; every `info` becomes an error value.
module be_lapack
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   implicit none
   private
   public :: solve_dense_multi, lapack_version_string, gemv

   interface
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
      subroutine dgemv(trans, m, n, alpha, a, lda, x, incx, beta, y, incy)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: m, n, lda, incx, incy
         real(wp), intent(in) :: alpha, beta, a(lda, *), x(*)
         real(wp), intent(inout) :: y(*)
      end subroutine dgemv
      subroutine ilaver(major, minor, patch)
         integer, intent(out) :: major, minor, patch
      end subroutine ilaver
   end interface

contains

   !> y = alpha a x + beta y (BLAS dgemv; a square, no temporaries).
   subroutine gemv(alpha, a, x, beta, y)
      real(wp), intent(in) :: alpha, beta, a(:, :), x(:)
      real(wp), intent(inout) :: y(:)
      call dgemv('N', size(a, 1), size(a, 2), alpha, a, size(a, 1), x, 1, beta, y, 1)
   end subroutine gemv

   !> Solve a x = b for every column of b in place (b becomes x).
   subroutine solve_dense_multi(a, b, error)
      real(wp), intent(inout) :: a(:, :), b(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ipiv(:)
      integer :: n, info
      character(len=80) :: msg
      n = size(a, 1)
      if (size(a, 2) /= n .or. size(b, 1) /= n) then
         call set_error(error, 'solve_dense_multi: matrix and right-hand side sizes differ')
         return
      end if
      allocate (ipiv(n))
      call dgesv(n, size(b, 2), a, n, ipiv, b, n, info)
      if (info < 0) then
         write (msg, '(a,i0,a)') 'solve_dense_multi: LAPACK dgesv argument ', -info, ' is invalid'
         call set_error(error, trim(msg))
      else if (info > 0) then
         write (msg, '(a,i0,a)') 'solve_dense_multi: matrix is singular (pivot ', info, ' is zero)'
         call set_error(error, trim(msg))
      end if
   end subroutine solve_dense_multi

   !> "major.minor.patch" of the linked LAPACK.
   function lapack_version_string() result(text)
      character(len=:), allocatable :: text
      integer :: major, minor, patch
      character(len=32) :: buf
      call ilaver(major, minor, patch)
      write (buf, '(i0,".",i0,".",i0)') major, minor, patch
      text = trim(buf)
   end function lapack_version_string

end module be_lapack
