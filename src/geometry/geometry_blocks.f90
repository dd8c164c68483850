!> Block topology and rounding (manual Sections 3.3 and 4.2 II): a block's
!> corner ring, its area, centroid and bounding box, and the rounding circle
!> of every corner. The lists themselves are model_geometry's; this is the
!> polygon work done on them when a block is made or reshaped.
module geometry_blocks
   use core_kinds, only: wp, ip
   use core_arrays, only: list_capacity
   use geometry_polygon, only: polygon_centroid, segment_distance
   use core_constants, only: pi
   use model_geometry, only: geometry_t, grow_blocks, grow_corners, kill_corners
   implicit none
   private
   public :: geometry_add_block, geometry_set_block_polygon, geometry_update_rounding
   public :: geometry_corner_rounding

contains

   !> Append a block with the given clockwise polygon; returns its id.
   subroutine geometry_add_block(geo, x, y, material, cons, id)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x(:), y(:)
      integer(ip), intent(in) :: material, cons
      integer(ip), intent(out) :: id
      integer(ip) :: mat, con
      ! copies first: a caller may pass elements of the lists grown below
      mat = material
      con = cons
      associate (b => geo%blocks)
         if (.not. allocated(b%live)) call grow_blocks(b, 64_ip)
         if (b%n >= size(b%live)) call grow_blocks(b, list_capacity(size(b%live), b%n + 1_ip))
         b%n = b%n + 1
         id = b%n
         b%live(id) = .true.
         b%material(id) = mat
         b%cons(id) = con
         b%first_corner(id) = 0
         b%ncorner(id) = 0
         b%fdef(id) = .false.
         b%sdef(id) = .false.
         if (allocated(b%exx)) then   ! SDEF fields (block_sdef_fields)
            b%exx(id) = 0.0_wp; b%eyy(id) = 0.0_wp; b%exy(id) = 0.0_wp
            b%dxx(id) = 0.0_wp; b%dyy(id) = 0.0_wp; b%dxy(id) = 0.0_wp
            b%sxx(id) = 0.0_wp; b%syy(id) = 0.0_wp; b%sxy(id) = 0.0_wp
            b%qxx(id) = 0.0_wp; b%qyy(id) = 0.0_wp; b%qxy(id) = 0.0_wp
         end if
         b%bstate(id) = 0
         b%zfirst(id) = 0
         b%nzone(id) = 0
         b%gfirst(id) = 0
         b%ngp(id) = 0
         b%addr(id) = 0
      end associate
      call geometry_set_block_polygon(geo, id, x, y)
   end subroutine geometry_add_block

   !> Replace the corner ring of block `id` (old corners go dead).
   subroutine geometry_set_block_polygon(geo, id, x, y)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      real(wp), intent(in) :: x(:), y(:)
      integer(ip) :: i, n, c, first, prev
      real(wp) :: xc, yc, area
      call kill_corners(geo, id)
      n = size(x)
      if (.not. allocated(geo%corners%live)) call grow_corners(geo%corners, 256_ip)
      if (geo%corners%n + n > size(geo%corners%live)) &
         call grow_corners(geo%corners, list_capacity(size(geo%corners%live), geo%corners%n + n))
      first = geo%corners%n + 1
      prev = first + n - 1
      do i = 1, n
         c = geo%corners%n + 1
         geo%corners%n = c
         geo%corners%live(c) = .true.
         geo%corners%x(c) = x(i)
         geo%corners%y(c) = y(i)
         geo%corners%block(c) = id
         geo%corners%prev(c) = prev
         geo%corners%next(c) = merge(first, c + 1_ip, i == n)
         geo%corners%gp(c) = 0
         geo%corners%addr(c) = 0
         prev = c
      end do
      geo%blocks%first_corner(id) = first
      geo%blocks%ncorner(id) = n
      call polygon_centroid(x, y, xc, yc, area)
      ! blocks are clockwise, so the counter-clockwise-positive area is negative
      geo%blocks%area(id) = -area
      geo%blocks%xc(id) = xc
      geo%blocks%yc(id) = yc
      geo%blocks%xmin(id) = minval(x)
      geo%blocks%xmax(id) = maxval(x)
      geo%blocks%ymin(id) = minval(y)
      geo%blocks%ymax(id) = maxval(y)
      call geometry_update_rounding(geo, id)
      geo%contacts_valid = .false.
      geo%domains_valid = .false.
   end subroutine geometry_set_block_polygon

   !> Rounding circle of every corner of block `id` (manual Section 3.3,
   !> Fig 3-3d): tangent to both edges at distance d from the corner, with
   !> d = min(round, half the shorter adjacent edge). Straight and re-entrant
   !> corners are not rounded (radius 0, centre at the corner): a circle
   !> tangent to both edges would lie outside the block.
   !>
   !> The manual uses one d for every corner, so a blunt corner's circle
   !> (radius d tan(theta/2)) can reach through another edge of a thin
   !> block, and the contact there starts overlapped. Here such a corner's
   !> d is reduced, for that corner only, to the largest value whose circle
   !> lies inside the block's polygon (never zero: the corner is away from
   !> the block's other edges). Tightly fitted blocks then start with every
   !> contact gap >= 0.
   subroutine geometry_update_rounding(geo, id)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      integer(ip), parameter :: nhalve = 60, nbisect = 50
      integer(ip) :: i, n, c, k
      real(wp), allocatable :: px(:), py(:)
      real(wp) :: rx, ry, r, dlo, dhi, dmid, rxl, ryl, rl
      n = geo%blocks%ncorner(id)
      allocate (px(n), py(n))
      c = geo%blocks%first_corner(id)
      do i = 1, n
         px(i) = geo%corners%x(c)
         py(i) = geo%corners%y(c)
         c = geo%corners%next(c)
      end do
      c = geo%blocks%first_corner(id)
      do i = 1, n
         call round_at(i, geo%round, rx, ry, r)
         if (r > 0.0_wp .and. .not. inside(i, rx, ry, r)) then
            ! halve d until the circle fits, then bisect between fit and misfit
            dhi = geo%round
            dlo = 0.0_wp
            rxl = px(i)
            ryl = py(i)
            rl = 0.0_wp
            do k = 1, nhalve + nbisect
               if (dlo > 0.0_wp) then
                  if (dhi - dlo <= 1.0e-6_wp*dlo) exit
                  dmid = 0.5_wp*(dlo + dhi)
               else
                  dmid = 0.5_wp*dhi
               end if
               call round_at(i, dmid, rx, ry, r)
               if (inside(i, rx, ry, r)) then
                  dlo = dmid
                  rxl = rx
                  ryl = ry
                  rl = r
               else
                  dhi = dmid
               end if
            end do
            rx = rxl
            ry = ryl
            r = rl
         end if
         geo%corners%rx(c) = rx
         geo%corners%ry(c) = ry
         geo%corners%radius(c) = r
         c = geo%corners%next(c)
      end do
   contains
      subroutine round_at(i, d, rx, ry, r)
         integer(ip), intent(in) :: i
         real(wp), intent(in) :: d
         real(wp), intent(out) :: rx, ry, r
         integer(ip) :: ip_, in_
         ip_ = merge(n, i - 1_ip, i == 1)
         in_ = merge(1_ip, i + 1_ip, i == n)
         call geometry_corner_rounding(px(ip_), py(ip_), px(i), py(i), px(in_), py(in_), &
                                       d, rx, ry, r)
      end subroutine round_at
      !> The circle keeps clear of every edge but the two it is tangent to.
      logical function inside(i, cx, cy, rad)
         integer(ip), intent(in) :: i
         real(wp), intent(in) :: cx, cy, rad
         integer(ip) :: j, j2
         real(wp) :: dist, t
         inside = .true.
         do j = 1, n
            j2 = merge(1_ip, j + 1_ip, j == n)
            if (j == i .or. j2 == i) cycle
            call segment_distance(cx, cy, px(j), py(j), px(j2), py(j2), dist, t)
            inside = .not. dist < rad
            if (.not. inside) return
         end do
      end function inside
   end subroutine geometry_update_rounding

   !> Rounding circle at corner w with previous corner p and next corner q
   !> of a clockwise polygon.
   pure subroutine geometry_corner_rounding(px, py, wx, wy, qx, qy, round, rx, ry, r)
      real(wp), intent(in) :: px, py, wx, wy, qx, qy, round
      real(wp), intent(out) :: rx, ry, r
      real(wp) :: ux, uy, vx, vy, lu, lv, d, theta, bx, by, bl
      ux = px - wx
      uy = py - wy
      vx = qx - wx
      vy = qy - wy
      lu = hypot(ux, uy)
      lv = hypot(vx, vy)
      rx = wx
      ry = wy
      r = 0.0_wp
      if (lu <= 0.0_wp .or. lv <= 0.0_wp) return
      ux = ux/lu
      uy = uy/lu
      vx = vx/lv
      vy = vy/lv
      ! interior angle: sweep clockwise from v (to next) to u (to previous)
      theta = modulo(atan2(vy, vx) - atan2(uy, ux), 2.0_wp*pi)
      if (theta >= pi*(1.0_wp - 1.0e-9_wp) .or. theta <= 0.0_wp) return
      d = min(round, 0.5_wp*min(lu, lv))
      bx = ux + vx
      by = uy + vy
      bl = hypot(bx, by)
      if (bl <= 0.0_wp) return
      r = d*tan(0.5_wp*theta)
      rx = wx + bx/bl*d/cos(0.5_wp*theta)
      ry = wy + by/bl*d/cos(0.5_wp*theta)
   end subroutine geometry_corner_rounding

end module geometry_blocks
