!> Block topology and rounding (manual Sections 3.3 and 4.2 II): a block's
!> corner ring, its area, centroid and bounding box, and the rounding circle
!> of every corner. The lists themselves are model_geometry's; this is the
!> polygon work done on them when a block is made or reshaped.
module geometry_blocks
   use core_kinds, only: wp, ip
   use core_arrays, only: list_capacity
   use geometry_polygon, only: polygon_centroid, segment_distance
   use core_constants, only: pi
   use core_sort, only: sort_order, lower_bound
   use model_geometry, only: geometry_t, grow_blocks, grow_corners, kill_corners
   implicit none
   private
   public :: geometry_add_block, geometry_set_block_polygon, geometry_update_rounding
   public :: geometry_corner_rounding, geometry_round_facing

   !> Share of the stretch between two facing rounded corners of different
   !> blocks whose arcs overlap (geometry_round_facing) that either corner's
   !> rounding length is cut to: 0.4 leaves a fifth of the stretch straight
   !> between the two arcs.
   real(wp), parameter, public :: facing_share = 0.4_wp

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

   !> Rounding of corners that face a corner of another block along a joint
   !> (docs/mechanics.md, "Facing corners"): corner w of block A and corner
   !> v of block B lie on one straight stretch of joint, v on an edge of w
   !> and w on an edge of v, the two edges running along the stretch
   !> towards each other. The rule of geometry_update_rounding (d at most
   !> half of each of the corner's own edges) does not see v: with
   !> d_w + d_v above the stretch |wv| the two arcs leave no straight part
   !> between them, the two blocks touch only where the arcs face each
   !> other (a gap, and one corner-corner contact standing for no length).
   !> Where the arcs leave no straight part (d_w + d_v > |wv|, judged on
   !> the roundings before the pass), each of the two corners' d is cut to
   !> facing_share*|wv|, leaving a fifth of the stretch straight (the circle
   !> is recomputed with the smaller d; it lies inside the larger one's
   !> corner, so it stays inside the block). Stretches whose arcs leave a
   !> straight part keep their rounding. Only rounded corners (radius > 0)
   !> on both sides: a straight vertex (a gridpoint) has no arc.
   !> The pass only reduces rounding, so running it again changes nothing
   !> (a cap stays when the facing block is deleted later); it runs when
   !> contacts are brought up to date after blocks changed (contact_rebuild,
   !> geometry_refresh). Corners are found through a grid of cells of
   !> round/facing_share (sorted cell keys): |wv| < d_w + d_v <= 2 round.
   subroutine geometry_round_facing(geo)
      type(geometry_t), intent(inout) :: geo
      real(wp), allocatable :: key(:), skey(:)
      integer(ip), allocatable :: order(:), list(:)
      integer(ip) :: n, c, m, i, ix, iy, jx, jy, lo, hi, v, side
      real(wp), allocatable :: dcap(:)
      real(wp) :: h, x0, y0, nyc, tol, s, cx, cy, r
      if (.not. allocated(geo%corners%live)) return
      if (.not. geo%round > 0.0_wp) return
      n = geo%corners%n
      h = geo%round/facing_share
      tol = max(geo%tol, 1.0e-9_wp*h)
      allocate (list(n))
      m = 0
      do c = 1, n
         if (.not. geo%corners%live(c)) cycle
         if (.not. geo%blocks%live(geo%corners%block(c))) cycle
         if (geo%corners%radius(c) <= 0.0_wp) cycle
         m = m + 1
         list(m) = c
      end do
      if (m < 2) return
      x0 = minval(geo%corners%x(list(1:m)))
      y0 = minval(geo%corners%y(list(1:m)))
      nyc = real(floor((maxval(geo%corners%y(list(1:m))) - y0)/h), wp) + 3.0_wp
      allocate (key(m), order(m))
      do i = 1, m
         key(i) = cell_key(floor((geo%corners%x(list(i)) - x0)/h), &
                           floor((geo%corners%y(list(i)) - y0)/h))
      end do
      call sort_order(key, order)
      list(1:m) = list(order)
      skey = key(order)
      ! the caps from the roundings as they stand, then applied
      allocate (dcap(m))
      do i = 1, m
         c = list(i)
         ix = floor((geo%corners%x(c) - x0)/h)
         iy = floor((geo%corners%y(c) - y0)/h)
         dcap(i) = huge(1.0_wp)
         do jx = ix - 1, ix + 1
            do jy = iy - 1, iy + 1
               call key_range(cell_key(jx, jy), lo, hi)
               do v = lo, hi
                  if (geo%corners%block(list(v)) == geo%corners%block(c)) cycle
                  do side = 1, 2
                     s = facing(c, list(v), side)
                     if (.not. s > 0.0_wp) cycle
                     if (rounding_length(c) + rounding_length(list(v)) > s) &
                        dcap(i) = min(dcap(i), facing_share*s)
                  end do
               end do
            end do
         end do
      end do
      do i = 1, m
         c = list(i)
         if (.not. dcap(i) < rounding_length(c)) cycle
         call geometry_corner_rounding(geo%corners%x(geo%corners%prev(c)), &
                                       geo%corners%y(geo%corners%prev(c)), &
                                       geo%corners%x(c), geo%corners%y(c), &
                                       geo%corners%x(geo%corners%next(c)), &
                                       geo%corners%y(geo%corners%next(c)), dcap(i), cx, cy, r)
         if (r > 0.0_wp) then
            geo%corners%rx(c) = cx
            geo%corners%ry(c) = cy
            geo%corners%radius(c) = r
         end if
      end do
   contains
      real(wp) function cell_key(jx, jy)
         integer(ip), intent(in) :: jx, jy
         cell_key = real(jx, wp)*nyc + real(jy, wp)
      end function cell_key
      !> Slots lo..hi of skey equal to k (hi < lo if none).
      subroutine key_range(k, lo, hi)
         real(wp), intent(in) :: k
         integer(ip), intent(out) :: lo, hi
         lo = lower_bound(skey, k)
         hi = lo - 1
         do while (hi < m)
            if (skey(hi + 1) /= k) exit
            hi = hi + 1
         end do
      end subroutine key_range
      !> Rounding length d of corner c as it stands: the distance from its
      !> vertex to the circle's tangent point on the edge to next(c).
      real(wp) function rounding_length(c) result(d)
         integer(ip), intent(in) :: c
         real(wp) :: ux, uy, lu
         d = 0.0_wp
         ux = geo%corners%x(geo%corners%next(c)) - geo%corners%x(c)
         uy = geo%corners%y(geo%corners%next(c)) - geo%corners%y(c)
         lu = hypot(ux, uy)
         if (.not. lu > 0.0_wp) return
         d = ((geo%corners%rx(c) - geo%corners%x(c))*ux + (geo%corners%ry(c) - geo%corners%y(c))*uy)/lu
      end function rounding_length
      !> Distance |wv| if corner v faces corner w along w's edge on `side`
      !> (1 the edge to next(w), 2 the one from prev(w)); 0 otherwise.
      real(wp) function facing(w, v, side) result(dist)
         integer(ip), intent(in) :: w, v, side
         integer(ip) :: q, t
         real(wp) :: ax, ay, la, sv, bx, by, lb
         dist = 0.0_wp
         q = merge(geo%corners%next(w), geo%corners%prev(w), side == 1)
         ax = geo%corners%x(q) - geo%corners%x(w)
         ay = geo%corners%y(q) - geo%corners%y(w)
         la = hypot(ax, ay)
         if (.not. la > 0.0_wp) return
         ax = ax/la
         ay = ay/la
         sv = (geo%corners%x(v) - geo%corners%x(w))*ax + (geo%corners%y(v) - geo%corners%y(w))*ay
         if (.not. (sv > tol .and. sv <= la + tol)) return
         if (abs((geo%corners%y(v) - geo%corners%y(w))*ax - (geo%corners%x(v) - geo%corners%x(w))*ay) > tol) &
            return
         ! an edge of v running back along the stretch towards w
         do t = 1, 2
            q = merge(geo%corners%next(v), geo%corners%prev(v), t == 1)
            bx = geo%corners%x(q) - geo%corners%x(v)
            by = geo%corners%y(q) - geo%corners%y(v)
            lb = hypot(bx, by)
            if (.not. lb > 0.0_wp) cycle
            if (bx*ax + by*ay > -0.5_wp*lb) cycle
            if (abs(bx*ay - by*ax) > tol + 1.0e-6_wp*lb) cycle
            dist = sv
            return
         end do
      end function facing
   end subroutine geometry_round_facing

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
