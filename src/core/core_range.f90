!> Coordinate ranges shared by many commands (manual Section 4.5, CHANGE):
!> a box `xl xu yl yu`, a clockwise quadrilateral `REG x1,y1 .. x4,y4`, or an
!> annulus `ANN xc yc r1 r2`. An unset range contains every point.
module core_range
   use core_kinds, only: wp
   implicit none
   private
   public :: range_t, range_all, range_box, range_region, range_annulus, in_range

   integer, parameter :: range_all = 0, range_box = 1, range_region = 2, range_annulus = 3
   !> relative tolerance of the box limits (see range_contains_point)
   real(wp), parameter, public :: range_tol_rel = 1.0e-6_wp

   type :: range_t
      integer :: kind = range_all
      real(wp) :: xl = 0.0_wp, xu = 0.0_wp, yl = 0.0_wp, yu = 0.0_wp   !< box
      real(wp) :: px(4) = 0.0_wp, py(4) = 0.0_wp                      !< region corners
      real(wp) :: xc = 0.0_wp, yc = 0.0_wp, r1 = 0.0_wp, r2 = 0.0_wp  !< annulus
   contains
      procedure :: contains_point => range_contains_point
   end type range_t

contains

   !> Box: inclusive with a small tolerance, xl - tx <= x <= xu + tx and
   !> yl - ty <= y <= yu + ty, tx = range_tol_rel times the largest of the
   !> x side and |xl|, |xu| (ty likewise from y alone: a y limit of 1e6 must
   !> not widen the x limits, issue 20; a line `0,0 yl,yu` takes the other
   !> axis's tolerance). The manual writes xl < x < xu, but an
   !> engineer who types `BOUND 0,12 10,10` or `BOUND 0 12 0 10` for a 12 x 10
   !> model means the points on those lines (docs/zones.md, "Ranges").
   !> Region: inside or on the quadrilateral (either orientation accepted).
   !> Annulus: r1 <= distance <= r2.
   pure logical function range_contains_point(this, x, y) result(inside)
      class(range_t), intent(in) :: this
      real(wp), intent(in) :: x, y
      real(wp) :: d, cross(4), tx, ty
      integer :: i, j
      select case (this%kind)
      case (range_box)
         tx = range_tol_rel*max(this%xu - this%xl, abs(this%xl), abs(this%xu))
         ty = range_tol_rel*max(this%yu - this%yl, abs(this%yl), abs(this%yu))
         ! a line on an axis (`0,0 yl,yu`) takes its tolerance from the other side
         if (tx == 0.0_wp) tx = ty
         if (ty == 0.0_wp) ty = tx
         inside = x >= this%xl - tx .and. x <= this%xu + tx .and. &
                  y >= this%yl - ty .and. y <= this%yu + ty
      case (range_region)
         do i = 1, 4
            j = merge(1, i + 1, i == 4)
            cross(i) = (this%px(j) - this%px(i))*(y - this%py(i)) &
                       - (this%py(j) - this%py(i))*(x - this%px(i))
         end do
         inside = all(cross <= 0.0_wp) .or. all(cross >= 0.0_wp)
      case (range_annulus)
         d = hypot(x - this%xc, y - this%yc)
         inside = d >= this%r1 .and. d <= this%r2
      case default
         inside = .true.
      end select
   end function range_contains_point

   !> (x, y) is in `range`, or no range was given (PRINT's optional range).
   pure logical function in_range(x, y, range)
      real(wp), intent(in) :: x, y
      type(range_t), intent(in), optional :: range
      in_range = .true.
      if (present(range)) in_range = range%contains_point(x, y)
   end function in_range

end module core_range
