!> Plane polygon and segment arithmetic shared by the geometry state and the
!> block-cutting and contact code. Polygons are passed as coordinate arrays;
!> UDEC blocks are stored clockwise, so their signed (counter-clockwise
!> positive) area is negative.
module geometry_polygon
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   implicit none
   private
   public :: polygon_signed_area, polygon_centroid, point_in_polygon
   public :: segment_distance, polygon_boundary_distance, polygon_is_simple
   public :: polygon_clip_convex_area
   public :: segment_intersection, require_clockwise_simple, segment_along_line

contains

   !> Error unless (x, y) is a simple polygon (tolerance tol) in clockwise
   !> order, the corners a user gives (BLOCK, JREGION): `cmd` names the
   !> command, `crossing` says what a self-intersection is for it.
   subroutine require_clockwise_simple(x, y, tol, cmd, crossing, error)
      real(wp), intent(in) :: x(:), y(:), tol
      character(len=*), intent(in) :: cmd, crossing
      type(error_t), allocatable, intent(out) :: error
      if (.not. polygon_is_simple(x, y, tol)) then
         call set_error(error, cmd//': '//crossing)
      else if (polygon_signed_area(x, y) >= 0.0_wp) then
         call set_error(error, cmd//': corners must be given in clockwise order')
      end if
   end subroutine require_clockwise_simple

   !> Signed area (shoelace), positive for counter-clockwise order.
   pure function polygon_signed_area(x, y) result(area)
      real(wp), intent(in) :: x(:), y(:)
      real(wp) :: area
      integer(ip) :: i, j, n
      n = size(x)
      area = 0.0_wp
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         ! products taken relative to the first vertex keep round-off small
         area = area + (x(i) - x(1))*(y(j) - y(1)) - (x(j) - x(1))*(y(i) - y(1))
      end do
      area = 0.5_wp*area
   end function polygon_signed_area

   !> Centroid and signed area of a polygon (centroid = vertex mean if degenerate).
   pure subroutine polygon_centroid(x, y, xc, yc, area)
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(out) :: xc, yc, area
      integer(ip) :: i, j, n
      real(wp) :: cr, sx, sy, x0, y0
      n = size(x)
      x0 = x(1)
      y0 = y(1)
      area = 0.0_wp
      sx = 0.0_wp
      sy = 0.0_wp
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         cr = (x(i) - x0)*(y(j) - y0) - (x(j) - x0)*(y(i) - y0)
         area = area + cr
         sx = sx + (x(i) + x(j) - 2.0_wp*x0)*cr
         sy = sy + (y(i) + y(j) - 2.0_wp*y0)*cr
      end do
      if (abs(area) > 0.0_wp) then
         xc = x0 + sx/(3.0_wp*area)
         yc = y0 + sy/(3.0_wp*area)
      else
         xc = sum(x)/real(n, wp)
         yc = sum(y)/real(n, wp)
      end if
      area = 0.5_wp*area
   end subroutine polygon_centroid

   !> Crossing-number test; points on the boundary may go either way, so
   !> callers that care combine it with `polygon_boundary_distance`.
   pure function point_in_polygon(x, y, px, py) result(inside)
      real(wp), intent(in) :: x(:), y(:), px, py
      logical :: inside
      integer(ip) :: i, j, n
      real(wp) :: xi
      n = size(x)
      inside = .false.
      j = n
      do i = 1, n
         if ((y(i) > py) .neqv. (y(j) > py)) then
            xi = x(i) + (py - y(i))*(x(j) - x(i))/(y(j) - y(i))
            if (px < xi) inside = .not. inside
         end if
         j = i
      end do
   end function point_in_polygon

   !> Segment a-b seen from the line through (x0,y0) with unit direction
   !> (ux,uy): `near` when neither end lies more than g off the line; sa, sb
   !> the ends' positions along it.
   pure subroutine segment_along_line(x0, y0, ux, uy, ax, ay, bx, by, g, near, sa, sb)
      real(wp), intent(in) :: x0, y0, ux, uy, ax, ay, bx, by, g
      logical, intent(out) :: near
      real(wp), intent(out) :: sa, sb
      near = .not. (abs(ux*(ay - y0) - uy*(ax - x0)) > g .or. &
                    abs(ux*(by - y0) - uy*(bx - x0)) > g)
      sa = ux*(ax - x0) + uy*(ay - y0)
      sb = ux*(bx - x0) + uy*(by - y0)
   end subroutine segment_along_line

   !> Distance from (px,py) to segment a-b; `t` is the clamped parameter.
   pure subroutine segment_distance(px, py, ax, ay, bx, by, dist, t)
      real(wp), intent(in) :: px, py, ax, ay, bx, by
      real(wp), intent(out) :: dist, t
      real(wp) :: dx, dy, l2
      dx = bx - ax
      dy = by - ay
      l2 = dx*dx + dy*dy
      if (l2 > 0.0_wp) then
         t = ((px - ax)*dx + (py - ay)*dy)/l2
         t = min(1.0_wp, max(0.0_wp, t))
      else
         t = 0.0_wp
      end if
      dist = hypot(px - (ax + t*dx), py - (ay + t*dy))
   end subroutine segment_distance

   !> Smallest distance from a point to the polygon boundary.
   pure function polygon_boundary_distance(x, y, px, py) result(dmin)
      real(wp), intent(in) :: x(:), y(:), px, py
      real(wp) :: dmin
      integer(ip) :: i, j, n
      real(wp) :: d, t
      n = size(x)
      dmin = huge(1.0_wp)
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         call segment_distance(px, py, x(i), y(i), x(j), y(j), d, t)
         dmin = min(dmin, d)
      end do
   end function polygon_boundary_distance

   !> Proper or touching intersection of segments p1-p2 and q1-q2 that are not
   !> parallel; `s` and `t` are the parameters on each. Parallel segments
   !> report no intersection: callers treat collinear contact through vertex
   !> distances instead.
   pure subroutine segment_intersection(p1x, p1y, p2x, p2y, q1x, q1y, q2x, q2y, &
                                        hit, s, t)
      real(wp), intent(in) :: p1x, p1y, p2x, p2y, q1x, q1y, q2x, q2y
      logical, intent(out) :: hit
      real(wp), intent(out) :: s, t
      real(wp) :: rx, ry, ux, uy, den, wx, wy, scale
      rx = p2x - p1x
      ry = p2y - p1y
      ux = q2x - q1x
      uy = q2y - q1y
      den = rx*uy - ry*ux
      scale = hypot(rx, ry)*hypot(ux, uy)
      hit = .false.
      s = 0.0_wp
      t = 0.0_wp
      if (abs(den) <= 1.0e-12_wp*scale .or. scale == 0.0_wp) return
      wx = q1x - p1x
      wy = q1y - p1y
      s = (wx*uy - wy*ux)/den
      t = (wx*ry - wy*rx)/den
      hit = s >= 0.0_wp .and. s <= 1.0_wp .and. t >= 0.0_wp .and. t <= 1.0_wp
   end subroutine segment_intersection

   !> True when no two edges meet except adjacent edges at their shared
   !> vertex, and no vertex lies within `tol` of a non-adjacent edge.
   pure function polygon_is_simple(x, y, tol) result(simple)
      real(wp), intent(in) :: x(:), y(:), tol
      logical :: simple
      integer(ip) :: i, j, n, i2, j2
      real(wp) :: s, t, d
      logical :: hit
      n = size(x)
      simple = n >= 3
      if (.not. simple) return
      do i = 1, n
         i2 = merge(1_ip, i + 1_ip, i == n)
         if (hypot(x(i2) - x(i), y(i2) - y(i)) <= tol) then
            simple = .false.
            return
         end if
         do j = 1, n
            if (j == i .or. j == i2) cycle
            j2 = merge(1_ip, j + 1_ip, j == n)
            ! vertex j against edge i (covers collinear overlaps and touches)
            call segment_distance(x(j), y(j), x(i), y(i), x(i2), y(i2), d, t)
            if (d <= tol) then
               simple = .false.
               return
            end if
            if (j2 == i .or. j > i) cycle
            call segment_intersection(x(i), y(i), x(i2), y(i2), x(j), y(j), x(j2), y(j2), &
                                      hit, s, t)
            if (hit) then
               simple = .false.
               return
            end if
         end do
      end do
   end function polygon_is_simple


   !> Area of the part of polygon (x, y) (simple, either orientation) that
   !> lies inside the convex polygon (cx, cy) (clockwise): the polygon is
   !> clipped by each edge of the convex one in turn (Sutherland-Hodgman);
   !> for a convex clipper the clipped ring may have degenerate edges but
   !> its area is exact.
   pure function polygon_clip_convex_area(x, y, cx, cy) result(area)
      real(wp), intent(in) :: x(:), y(:), cx(:), cy(:)
      real(wp) :: area
      real(wp), allocatable :: ax(:), ay(:), bx(:), by(:)
      integer(ip) :: i, j, k, n, m, nc
      real(wp) :: ex, ey, si, sj, t
      n = size(x)
      nc = size(cx)
      ax = x
      ay = y
      m = n
      do k = 1, nc
         if (m == 0) exit
         j = merge(1_ip, k + 1_ip, k == nc)
         ex = cx(j) - cx(k)
         ey = cy(j) - cy(k)
         n = m
         m = 0
         ! each crossing adds at most one point
         allocate (bx(2*n), by(2*n))
         do i = 1, n
            ! inside a clockwise polygon = right of each edge: cross <= 0
            si = ex*(ay(i) - cy(k)) - ey*(ax(i) - cx(k))
            j = merge(1_ip, i + 1_ip, i == n)
            sj = ex*(ay(j) - cy(k)) - ey*(ax(j) - cx(k))
            if (si <= 0.0_wp) then
               m = m + 1
               bx(m) = ax(i)
               by(m) = ay(i)
            end if
            if ((si < 0.0_wp .and. sj > 0.0_wp) .or. (si > 0.0_wp .and. sj < 0.0_wp)) then
               t = si/(si - sj)
               m = m + 1
               bx(m) = ax(i) + t*(ax(j) - ax(i))
               by(m) = ay(i) + t*(ay(j) - ay(i))
            end if
         end do
         ax = bx(1:m)
         ay = by(1:m)
         deallocate (bx, by)
      end do
      area = 0.0_wp
      if (m >= 3) area = abs(polygon_signed_area(ax(1:m), ay(1:m)))
   end function polygon_clip_convex_area

end module geometry_polygon
