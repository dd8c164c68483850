!> REINFORCE mat x1 y1 x2 y2 and CABLE x1 y1 x2 y2 npoin mats asteel matg
!> <preten> (UDEC manual (ICG1.5, 1989), Section 4.5): where the elements go.
!>
!> REINFORCE: the line from (x1, y1) to (x2, y2) crosses the block edges;
!> where it leaves a block and enters another within the rounding length
!> (ROUND), one element joins the two (a joint crossing). Its material points
!> are the crossings on each block's edge.
!>
!> CABLE: npoin nodes evenly from (x1, y1) to (x2, y2); when (x1, y1) lies
!> in no block (inside an excavation) the first node moves to where the line
!> first enters a block (the manual's note). Each node is hosted by the zone
!> of a zoned block that contains it (weights Eq. 49), else by the rigid
!> block that contains it, else it is free. Node k carries the cable length
!> between the midpoints of its elements (glen), end nodes half an element.
module reinforce_generate
   use core_kinds, only: wp, ip
   use core_sort, only: sort_order
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_geometry, only: geometry_t, block_contains_point
   use model_reinforcement, only: reinforcement_t, reinf_add, cable_add_node, cable_add_element
   implicit none
   private
   public :: reinforce_build, cable_build, locate_host

contains

   !> Elements of REINFORCE (module header) appended to rf%reinf; `made` their
   !> count (0 when the line crosses no joint: the caller warns).
   subroutine reinforce_build(rf, geo, mat, x1, y1, x2, y2, made, error)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: mat
      real(wp), intent(in) :: x1, y1, x2, y2
      integer(ip), intent(out) :: made
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: ht(:), hs(:)
      integer(ip), allocatable :: hb(:), hc(:)
      logical, allocatable :: hexit(:), used(:)
      integer(ip) :: i, j, k, nh, ex_i, b1, b2, c1, c2
      real(wp) :: len, dx, dy, ax, ay, tx, ty, l, px1, py1, px2, py2, tol
      made = 0
      dx = x2 - x1
      dy = y2 - y1
      len = hypot(dx, dy)
      if (.not. len > 0.0_wp) then
         call set_error(error, 'REINFORCE: the line has zero length (x1 y1 = x2 y2)')
         return
      end if
      if (mat < 1) then
         call set_error(error, 'REINFORCE: the material number must be >= 1, got '//itoa(mat))
         return
      end if
      ax = dx/len
      ay = dy/len
      call crossings(geo, x1, y1, x2, y2, ht, hb, hc, hs, hexit)
      nh = size(ht, kind=ip)
      tol = max(geo%round, 1.0e-9_wp*len)/len
      allocate (used(nh))
      used = .false.
      do ex_i = 1, nh
         if (.not. hexit(ex_i)) cycle
         ! the entry into another block nearest after this exit (a tie in t
         ! may sort either way)
         k = 0
         do j = 1, nh
            if (hexit(j) .or. used(j) .or. hb(j) == hb(ex_i)) cycle
            if (ht(j) < ht(ex_i) - 1.0e-9_wp .or. ht(j) - ht(ex_i) > tol) cycle
            if (k > 0) then
               if (.not. ht(j) < ht(k)) cycle   ! not nearer than the one found
            end if
            k = j
         end do
         if (k == 0) cycle
         used(k) = .true.
         b1 = hb(ex_i)
         b2 = hb(k)
         c1 = hc(ex_i)
         c2 = hc(k)
         associate (co => geo%corners)
            i = co%next(c1)
            tx = co%x(i) - co%x(c1); ty = co%y(i) - co%y(c1)
            l = hypot(tx, ty)
            tx = tx/l; ty = ty/l
            px1 = x1 + ht(ex_i)*dx; py1 = y1 + ht(ex_i)*dy
            px2 = x1 + ht(k)*dx; py2 = y1 + ht(k)*dy
            j = co%next(c2)
            call reinf_add(rf%reinf, mat, b1, b2, co%gp(c1), co%gp(i), hs(ex_i), co%gp(c2), &
                           co%gp(j), hs(k), px1, py1, px2, py2, ax, ay, tx, ty)
         end associate
         made = made + 1
      end do
   end subroutine reinforce_build

   !> Where the segment crosses block edges, sorted along it: parameter t,
   !> block, edge (its first corner), fraction s along the edge, and whether
   !> the segment leaves the block there.
   subroutine crossings(geo, x1, y1, x2, y2, ht, hb, hc, hs, hexit)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2
      real(wp), allocatable, intent(out) :: ht(:), hs(:)
      integer(ip), allocatable, intent(out) :: hb(:), hc(:)
      logical, allocatable, intent(out) :: hexit(:)
      integer(ip) :: b, c, cn, i, k
      integer(ip), allocatable :: order(:)
      real(wp) :: rx, ry, ux, uy, den, wx, wy, s, t
      logical :: dup
      allocate (ht(0), hs(0), hb(0), hc(0), hexit(0))
      rx = x2 - x1
      ry = y2 - y1
      associate (bl => geo%blocks, co => geo%corners)
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            c = bl%first_corner(b)
            do i = 1, bl%ncorner(b)
               cn = co%next(c)
               ux = co%x(cn) - co%x(c)
               uy = co%y(cn) - co%y(c)
               den = rx*uy - ry*ux
               if (abs(den) > 1.0e-12_wp*hypot(rx, ry)*hypot(ux, uy)) then
                  wx = co%x(c) - x1
                  wy = co%y(c) - y1
                  t = (wx*uy - wy*ux)/den
                  s = (wx*ry - wy*rx)/den
                  if (t >= 0.0_wp .and. t <= 1.0_wp .and. s >= 0.0_wp .and. s <= 1.0_wp) then
                     ! a crossing through a corner is found on both edges: keep one
                     dup = .false.
                     do k = 1, size(hb)
                        if (hb(k) == b .and. abs(ht(k) - t) < 1.0e-9_wp) dup = .true.
                     end do
                     if (.not. dup) then
                        ! clockwise ring: the block is right of the edge, outward is left
                        ht = [ht, t]; hb = [hb, b]; hc = [hc, c]; hs = [hs, s]
                        hexit = [hexit, rx*(-uy) + ry*ux > 0.0_wp]
                     end if
                  end if
               end if
               c = cn
            end do
         end do
      end associate
      ! in order along the segment (stable: equal t keep the order found)
      allocate (order(size(ht)))
      call sort_order(ht, order)
      ht = ht(order)
      hb = hb(order)
      hc = hc(order)
      hs = hs(order)
      hexit = hexit(order)
   end subroutine crossings

   !> The host of point (x, y): zone z of an FDEF block b with weights w, or a
   !> rigid block b (z = 0), or none (b = 0).
   subroutine locate_host(geo, x, y, b, z, w)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      integer(ip), intent(out) :: b, z
      real(wp), intent(out) :: w(3)
      integer(ip) :: i, k
      real(wp) :: a, a1, a2, a3, tol
      b = 0
      z = 0
      w = 0.0_wp
      associate (bl => geo%blocks, zn => geo%zones, gp => geo%gridpoints)
         do i = 1, bl%n
            if (.not. bl%live(i)) cycle
            if (x < bl%xmin(i) - 1.0e-9_wp .or. x > bl%xmax(i) + 1.0e-9_wp .or. &
                y < bl%ymin(i) - 1.0e-9_wp .or. y > bl%ymax(i) + 1.0e-9_wp) cycle
            if (bl%fdef(i) .and. bl%nzone(i) > 0) then
               do k = bl%zfirst(i), bl%zfirst(i) + bl%nzone(i) - 1
                  if (.not. zn%live(k)) cycle
                  a = tri(gp%x(zn%g1(k)), gp%y(zn%g1(k)), gp%x(zn%g2(k)), gp%y(zn%g2(k)), &
                          gp%x(zn%g3(k)), gp%y(zn%g3(k)))
                  if (a <= 0.0_wp) cycle
                  tol = 1.0e-9_wp*a
                  a1 = tri(x, y, gp%x(zn%g2(k)), gp%y(zn%g2(k)), gp%x(zn%g3(k)), gp%y(zn%g3(k)))
                  a2 = tri(gp%x(zn%g1(k)), gp%y(zn%g1(k)), x, y, gp%x(zn%g3(k)), gp%y(zn%g3(k)))
                  a3 = tri(gp%x(zn%g1(k)), gp%y(zn%g1(k)), gp%x(zn%g2(k)), gp%y(zn%g2(k)), x, y)
                  if (a1 >= -tol .and. a2 >= -tol .and. a3 >= -tol) then
                     b = i
                     z = k
                     w = [max(a1, 0.0_wp), max(a2, 0.0_wp), max(a3, 0.0_wp)]
                     w = w/sum(w)
                     return
                  end if
               end do
            else if (inside_block(i)) then
               b = i
               return
            end if
         end do
      end associate
   contains
      pure real(wp) function tri(xa, ya, xb, yb, xc, yc) result(ar)
         real(wp), intent(in) :: xa, ya, xb, yb, xc, yc
         ar = 0.5_wp*((xb - xa)*(yc - ya) - (xc - xa)*(yb - ya))
      end function tri
      !> Crossing-number test on the block's corner ring (a point on an edge
      !> counts as inside).
      logical function inside_block(id) result(inside)
         integer(ip), intent(in) :: id
         integer(ip) :: c, cn, j
         real(wp) :: ex, ey, t, d
         inside = .false.
         associate (co => geo%corners)
            c = geo%blocks%first_corner(id)
            do j = 1, geo%blocks%ncorner(id)
               cn = co%next(c)
               ex = co%x(cn) - co%x(c)
               ey = co%y(cn) - co%y(c)
               t = ((x - co%x(c))*ex + (y - co%y(c))*ey)/(ex*ex + ey*ey)
               t = min(1.0_wp, max(0.0_wp, t))
               d = hypot(x - co%x(c) - t*ex, y - co%y(c) - t*ey)
               if (d <= 1.0e-9_wp*hypot(ex, ey)) then
                  inside = .true.
                  return
               end if
               c = cn
            end do
         end associate
         inside = block_contains_point(geo, id, x, y)
      end function inside_block
   end subroutine locate_host

   !> Nodes and elements of CABLE (module header) appended to rf.
   subroutine cable_build(rf, geo, x1, y1, x2, y2, npoin, mats, asteel, matg, preten, error)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2, asteel, preten
      integer(ip), intent(in) :: npoin, mats, matg
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: ht(:), hs(:)
      integer(ip), allocatable :: hb(:), hc(:)
      logical, allocatable :: hexit(:)
      real(wp) :: xs, ys, len, h, x, y, w(3), gl
      integer(ip) :: b, z, k, id0, k1, nfree
      ! the arguments, checked in order: the first that is off is refused
      if (npoin < 2) then
         call set_error(error, 'CABLE: npoin (the number of nodes) must be >= 2, got '//itoa(npoin))
      else if (.not. asteel > 0.0_wp) then
         call set_error(error, 'CABLE: asteel (the steel cross-section area) must be > 0')
      else if (mats < 1 .or. matg < 1) then
         call set_error(error, 'CABLE: the material numbers mats and matg must be >= 1')
      else if (preten < 0.0_wp) then
         call set_error(error, 'CABLE: the pretension must be >= 0 (a force)')
      end if
      if (allocated(error)) return
      xs = x1
      ys = y1
      call locate_host(geo, xs, ys, b, z, w)
      if (b == 0) then
         ! the first node on the periphery where the line enters the rock
         call crossings(geo, x1, y1, x2, y2, ht, hb, hc, hs, hexit)
         do k = 1, size(ht, kind=ip)
            if (.not. hexit(k)) then
               xs = x1 + ht(k)*(x2 - x1)
               ys = y1 + ht(k)*(y2 - y1)
               exit
            end if
         end do
      end if
      len = hypot(x2 - xs, y2 - ys)
      if (.not. len > 0.0_wp) then
         call set_error(error, 'CABLE: the cable has zero length in the rock')
         return
      end if
      h = len/real(npoin - 1, wp)
      rf%ncable = rf%ncable + 1
      id0 = rf%nodes%n
      nfree = 0
      do k = 0, npoin - 1
         x = xs + real(k, wp)/real(npoin - 1, wp)*(x2 - xs)
         y = ys + real(k, wp)/real(npoin - 1, wp)*(y2 - ys)
         call locate_host(geo, x, y, b, z, w)
         if (b == 0) nfree = nfree + 1
         gl = h
         if (k == 0 .or. k == npoin - 1) gl = 0.5_wp*h
         call cable_add_node(rf%nodes, rf%ncable, b, z, w, x, y, matg, gl)
      end do
      do k = 1, npoin - 1
         k1 = id0 + k
         call cable_add_element(rf%elements, rf%ncable, k1, k1 + 1, mats, asteel, h, preten)
      end do
   end subroutine cable_build

end module reinforce_generate
