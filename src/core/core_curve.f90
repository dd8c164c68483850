!> Positions along a space-filling curve (issue 23: storage order). Points
!> close along the Hilbert curve are close in the plane, and a stretch of
!> the curve covers a compact patch of it, so a loop over items sorted by
!> their curve position revisits what its neighbours loaded while it is
!> still in the cache, whatever the size of the model.
!>
!> Reference: the Hilbert curve of order k visits the 4**k cells of a
!> 2**k x 2**k grid, each once, consecutive cells sharing a side (D. Hilbert,
!> "Ueber die stetige Abbildung einer Linie auf ein Flaechenstueck", Math.
!> Ann. 38, 1891); the index of a cell is computed quadrant by quadrant
!> from the top bit down, turning the frame in the lower quadrants.
module core_curve
   use core_kinds, only: wp, ip, i8
   use core_sort, only: sort_order
   implicit none
   private
   public :: hilbert_index, curve_keys, curve_sort

   !> Cells per side of the grid curve_keys uses: 2**curve_bits.
   integer, parameter :: curve_bits = 20

contains

   !> Position (0 .. 4**order - 1) of cell (ix, iy), 0 <= ix, iy < 2**order,
   !> along the Hilbert curve of that order.
   pure integer(i8) function hilbert_index(ix, iy, order) result(d)
      integer(i8), intent(in) :: ix, iy
      integer, intent(in) :: order
      integer(i8) :: x, y, s, rx, ry, t, last
      x = ix
      y = iy
      d = 0
      last = ishft(1_i8, order) - 1
      s = ishft(1_i8, order - 1)
      do while (s > 0)
         rx = merge(1_i8, 0_i8, iand(x, s) /= 0)
         ry = merge(1_i8, 0_i8, iand(y, s) /= 0)
         d = d + s*s*ieor(3_i8*rx, ry)
         ! turn the quadrant's frame so the sub-curve starts where it should
         if (ry == 0) then
            if (rx == 1) then
               x = last - x
               y = last - y
            end if
            t = x
            x = y
            y = t
         end if
         s = ishft(s, -1)
      end do
   end function hilbert_index

   !> Curve position of each point (x(k), y(k)) on a 2**curve_bits grid
   !> laid over the points' bounding box (as a real: exact, below 2**53).
   !> Points outside the finite range (a block thrown away) go to the end.
   subroutine curve_keys(x, y, keys)
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(out) :: keys(:)
      real(wp) :: x0, x1, y0, y1, h
      integer(ip) :: k
      integer(i8) :: ix, iy, cells
      cells = ishft(1_i8, curve_bits)
      x0 = huge(1.0_wp); y0 = huge(1.0_wp); x1 = -huge(1.0_wp); y1 = -huge(1.0_wp)
      do k = 1, size(x, kind=ip)
         if (.not. finite(x(k), y(k))) cycle
         x0 = min(x0, x(k)); x1 = max(x1, x(k))
         y0 = min(y0, y(k)); y1 = max(y1, y(k))
      end do
      h = max(x1 - x0, y1 - y0)/real(cells - 1_i8, wp)
      if (.not. (h > 0.0_wp .and. h <= huge(1.0_wp))) h = 1.0_wp
      do k = 1, size(x, kind=ip)
         if (.not. finite(x(k), y(k))) then
            keys(k) = real(cells, wp)**2
            cycle
         end if
         ix = min(cells - 1_i8, max(0_i8, int((x(k) - x0)/h, i8)))
         iy = min(cells - 1_i8, max(0_i8, int((y(k) - y0)/h, i8)))
         keys(k) = real(hilbert_index(ix, iy, curve_bits), wp)
      end do
   contains
      pure logical function finite(a, b)
         real(wp), intent(in) :: a, b
         finite = abs(a) <= huge(1.0_wp) .and. abs(b) <= huge(1.0_wp)
      end function finite
   end subroutine curve_keys

   !> The permutation putting points in curve order (stable: points of one
   !> cell keep their input order).
   subroutine curve_sort(x, y, order)
      real(wp), intent(in) :: x(:), y(:)
      integer(ip), intent(out) :: order(:)
      real(wp), allocatable :: keys(:)
      allocate (keys(size(x)))
      call curve_keys(x, y, keys)
      call sort_order(keys, order)
   end subroutine curve_sort

end module core_curve
