!> Contact detection from block polygons (manual Section 3.3; UPCON).
!>
!> Broad phase: contact_broadphase (bin grid, O(number of blocks)).
!> Narrow phase: every corner of one block within `gap` of the other block's
!> boundary is a contact point (corner-corner when it meets a corner,
!> otherwise corner-edge); an edge-edge contact is the two corner-edge (or
!> corner-corner) contacts at the ends of the shared stretch, each carrying
!> half its length (Fig 3-3b). Corner-only touches get length 0.
!> A corner that fills a re-entrant corner of the other block (the plug of a
!> TUNNEL at a vertex of the ring) makes two corner-edge contacts, one with
!> each edge of the re-entrant corner, each carrying half of its own edge's
!> shared stretch (corner_fills_reflex; docs/mechanics.md).
module contact_detection
   use core_kinds, only: wp, ip, i1
   use geometry_polygon, only: segment_distance, segment_along_line
   use core_curve, only: curve_sort
   use core_sort, only: counts_to_starts
   use model_geometry, only: geometry_t, geometry_block_polygon, geometry_add_contact, &
                             geometry_permute_contacts
   use contact_broadphase, only: broadphase_pairs
   use contact_kinematics, only: contact_geometry, corner_fills_reflex
   use contact_update, only: contact_margin
   use model_address, only: address_keep_contacts
   use geometry_blocks, only: geometry_round_facing
   implicit none
   private
   public :: contact_rebuild

contains

   !> Full rebuild of the contact list (UPCON). Contact ids restart at 1,
   !> in the order of their first blocks' centroids along a Hilbert curve
   !> (issue 23; contacts of one first block in the order found): the
   !> contact loops of the cycle then gather each block's and corner's data
   !> while their neighbours' contacts still hold it in the cache, at any
   !> model size.
   !> `gap` (default 10*geo%tol) is how far apart two boundaries may be and
   !> still be in contact.
   subroutine contact_rebuild(geo, gap)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in), optional :: gap
      real(wp) :: g, gp, nx, ny, px, py
      integer(ip) :: npair, k, c
      integer(ip), allocatable :: pa(:), pb(:)
      g = 10.0_wp*geo%tol
      if (present(gap)) g = gap
      ! corners facing a corner of another block across a stretch shorter
      ! than their rounding lengths (geometry_round_facing)
      call geometry_round_facing(geo)
      ! the 1989 addresses of the contacts about to be overwritten
      call address_keep_contacts(geo)
      geo%contacts%n = 0
      geo%domains_valid = .false.
      geo%contacts_valid = .true.
      call broadphase_pairs(geo, g, npair, pa, pb)
      do k = 1, npair
         call pair_contacts(geo, pa(k), pb(k), g)
      end do
      ! settle kind and normal with the contact kinematics the
      ! cycle uses (contact_kinematics): a corner met at a vertex of the
      ! other block that is a straight corner (e.g. a gridpoint on an FDEF
      ! edge at a T-junction) is a corner-edge contact with the edge's
      ! normal, not a corner-corner one along the line of the circle centres
      ! (which leans 45 degrees at a rounded right-angled corner); INSITU
      ! and the first cycle must see the same normal. The point stays at
      ! the vertex (domains are built from it; the cycle moves it onto the
      ! rounded surfaces) and the gap 0 (the set-up's blocks touch exactly,
      ! see engine_cycle) -- except for a contact of length 0, which stands
      ! for no stretch of joint: the corners of two diagonal neighbours at
      ! a joint crossing, whose rounded corners are 2 d (sqrt 2 - 1) apart
      ! at right angles. It starts with its geometric gap, open, so the
      ! first cycle does not see it open by that gap from a closed state
      ! (with a tensile strength -- a glued joint -- that pulled the four
      ! corners of every crossing together with JKN CLEMIN times the gap).
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         call contact_geometry(geo, c, 1.0e-3_wp*contact_margin(geo), gp, nx, ny, px, py)
         geo%contacts%nx(c) = nx
         geo%contacts%ny(c) = ny
         if (geo%contacts%length(c) <= 0.0_wp .and. gp > 0.0_wp) geo%contacts%gap(c) = gp
      end do
      call order_along_curve(geo)
   end subroutine contact_rebuild

   !> Number the contacts of a fresh list along the curve (nothing refers to
   !> contact ids yet: domains and addresses come after): the live blocks in
   !> curve order of their centroids, then the contacts by their first
   !> blocks' places in it (a counting sort: stable, no key per contact).
   subroutine order_along_curve(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip), allocatable :: order(:), live(:), border(:), rank(:), start(:)
      integer(ip) :: n, nb, b, c, k
      n = geo%contacts%n
      if (n < 2) return
      live = pack([(b, b=1, geo%blocks%n)], geo%blocks%live(1:geo%blocks%n))
      nb = size(live, kind=ip)
      allocate (border(nb), rank(geo%blocks%n), start(nb + 2), order(n))
      call curve_sort(geo%blocks%xc(live), geo%blocks%yc(live), border)
      rank = 0
      do k = 1, nb
         rank(live(border(k))) = k
      end do
      ! bucket rank(block1) + 1 (a contact of a block gone, if any: bucket 1)
      start = 0
      do c = 1, n
         k = rank(geo%contacts%block1(c)) + 1
         start(k + 1) = start(k + 1) + 1
      end do
      call counts_to_starts(start)
      do c = 1, n
         k = rank(geo%contacts%block1(c)) + 1
         order(start(k)) = c
         start(k) = start(k) + 1
      end do
      call geometry_permute_contacts(geo, order)
   end subroutine order_along_curve

   !> Contacts between blocks b1 < b2.
   subroutine pair_contacts(geo, b1, b2, g)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: b1, b2
      real(wp), intent(in) :: g
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
      integer(ip), allocatable :: id1(:), id2(:)
      integer(ip) :: n1, n2, i, j, i2, j2, m, k, c
      real(wp) :: ux, uy, li, sa, sb, lo, hi, dx, dy, r
      logical :: near
      ! registry of contact points of this pair
      real(wp), allocatable :: px(:), py(:), plen(:)
      integer(ip), allocatable :: pc1(:), pc2(:), pe1(:), pe2(:)
      !> the point is one of the two contacts of a corner filling a
      !> re-entrant corner: it takes length only from its own edge's stretch
      logical, allocatable :: psplit(:)
      integer(ip) :: m0
      call geometry_block_polygon(geo, b1, x1, y1, id1)
      call geometry_block_polygon(geo, b2, x2, y2, id2)
      n1 = size(x1)
      n2 = size(x2)
      ! room for a second contact at every point (re-entrant corners)
      allocate (px(2*(n1 + n2)), py(2*(n1 + n2)), plen(2*(n1 + n2)), pc1(2*(n1 + n2)), &
                pc2(2*(n1 + n2)), pe1(2*(n1 + n2)), pe2(2*(n1 + n2)), psplit(2*(n1 + n2)))
      psplit = .false.
      m = 0
      call corners_near_edges(x1, y1, id1, x2, y2, id2, .true.)
      call corners_near_edges(x2, y2, id2, x1, y1, id1, .false.)
      if (m == 0) return
      ! a corner filling a re-entrant corner of the other block: one contact
      ! with each of the re-entrant corner's edges (edges are named by their
      ! first corner: the edge ending at r and the edge starting at r)
      m0 = m
      do k = 1, m0
         if (pc1(k) <= 0 .or. pc2(k) <= 0) cycle
         if (corner_fills_reflex(geo, pc1(k), pc2(k), g)) then
            m = m + 1
            px(m) = px(k); py(m) = py(k); plen(m) = 0.0_wp
            pc1(m) = pc1(k); pc2(m) = 0; pe1(m) = 0; pe2(m) = pc2(k)
            pe2(k) = geo%corners%prev(pc2(k))
            pc2(k) = 0
            psplit(k) = .true.
            psplit(m) = .true.
         else if (corner_fills_reflex(geo, pc2(k), pc1(k), g)) then
            m = m + 1
            px(m) = px(k); py(m) = py(k); plen(m) = 0.0_wp
            pc1(m) = 0; pc2(m) = pc2(k); pe1(m) = pc1(k); pe2(m) = 0
            pe1(k) = geo%corners%prev(pc1(k))
            pc1(k) = 0
            psplit(k) = .true.
            psplit(m) = .true.
         end if
      end do
      ! shared stretches: antiparallel collinear edges; half length to each end
      do i = 1, n1
         i2 = merge(1_ip, i + 1_ip, i == n1)
         li = hypot(x1(i2) - x1(i), y1(i2) - y1(i))
         if (li <= 0.0_wp) cycle
         ux = (x1(i2) - x1(i))/li
         uy = (y1(i2) - y1(i))/li
         do j = 1, n2
            j2 = merge(1_ip, j + 1_ip, j == n2)
            call segment_along_line(x1(i), y1(i), ux, uy, x2(j), y2(j), x2(j2), y2(j2), g, &
                                    near, sa, sb)
            if (.not. near) cycle
            if (ux*(x2(j2) - x2(j)) + uy*(y2(j2) - y2(j)) >= 0.0_wp) cycle
            lo = max(0.0_wp, min(sa, sb))
            hi = min(li, max(sa, sb))
            if (hi - lo <= g) cycle
            call add_length(x1(i) + lo*ux, y1(i) + lo*uy, 0.5_wp*(hi - lo), id1(i), id2(j))
            call add_length(x1(i) + hi*ux, y1(i) + hi*uy, 0.5_wp*(hi - lo), id1(i), id2(j))
         end do
      end do
      do k = 1, m
         call geometry_add_contact(geo, c)
         associate (ct => geo%contacts)
            ct%block1(c) = b1
            ct%block2(c) = b2
            ! one of pc1 and pe1 is 0, one of pc2 and pe2 (register)
            ct%end1(c) = max(pc1(k), pe1(k))
            ct%end2(c) = max(pc2(k), pe2(k))
            ct%x(c) = px(k)
            ct%y(c) = py(k)
            ct%length(c) = plen(k)
            ct%jcons(c) = int(geo%jcons_default, i1)
            ! manual 4.5 CHANGE: "All contacts initially default to JMAT=1";
            ! the block material is the default only for contacts made
            ! after cycle 1 (SET JMATDF, contact_update)
            ct%jmat(c) = merge(geo%jmat_default, 1, geo%jmat_default > 0)
            if (pc1(k) > 0 .and. pc2(k) > 0) then
               ct%kind(c) = 1
               ! line of centres of the rounding circles (Fig 3-3d)
               dx = geo%corners%rx(pc2(k)) - geo%corners%rx(pc1(k))
               dy = geo%corners%ry(pc2(k)) - geo%corners%ry(pc1(k))
               r = hypot(dx, dy)
               if (r > g) then
                  ct%nx(c) = dx/r
                  ct%ny(c) = dy/r
               else
                  ! both corners unrounded: outward bisector of block1's corner
                  call corner_outward(geo, pc1(k), ct%nx(c), ct%ny(c))
               end if
            else if (pc1(k) > 0) then
               ct%kind(c) = 2
               call edge_normal(geo, pe2(k), -1.0_wp, ct%nx(c), ct%ny(c))
            else
               ct%kind(c) = 3
               call edge_normal(geo, pe1(k), 1.0_wp, ct%nx(c), ct%ny(c))
            end if
         end associate
      end do
   contains
      !> Each corner of polygon a within g of an edge of polygon b: a
      !> corner-corner point when it is within g of one of the edge's ends,
      !> else a corner-edge point. `a_first`: polygon a is block b1's.
      subroutine corners_near_edges(xa, ya, ida, xb, yb, idb, a_first)
         real(wp), intent(in) :: xa(:), ya(:), xb(:), yb(:)
         integer(ip), intent(in) :: ida(:), idb(:)
         logical, intent(in) :: a_first
         integer(ip) :: ia, jb, jb2, nb
         real(wp) :: dist, tpar
         nb = size(xb)
         do ia = 1, size(xa)
            do jb = 1, nb
               jb2 = merge(1_ip, jb + 1_ip, jb == nb)
               call segment_distance(xa(ia), ya(ia), xb(jb), yb(jb), xb(jb2), yb(jb2), dist, tpar)
               if (dist > g) cycle
               if (hypot(xa(ia) - xb(jb), ya(ia) - yb(jb)) <= g) then
                  call register_as(a_first, xa(ia), ya(ia), ida(ia), idb(jb), 0_ip)
               else if (hypot(xa(ia) - xb(jb2), ya(ia) - yb(jb2)) <= g) then
                  call register_as(a_first, xa(ia), ya(ia), ida(ia), idb(jb2), 0_ip)
               else
                  call register_as(a_first, xa(ia), ya(ia), ida(ia), 0_ip, idb(jb))
               end if
            end do
         end do
      end subroutine corners_near_edges

      !> Corner ca at (xp, yp) touching corner cb or edge eb of the other
      !> block; `a_first`: ca is block b1's.
      subroutine register_as(a_first, xp, yp, ca, cb, eb)
         logical, intent(in) :: a_first
         real(wp), intent(in) :: xp, yp
         integer(ip), intent(in) :: ca, cb, eb
         if (a_first) then
            call register(xp, yp, ca, cb, 0_ip, eb)
         else
            call register(xp, yp, cb, ca, eb, 0_ip)
         end if
      end subroutine register_as

      subroutine register(xp, yp, c1, c2, e1, e2)
         real(wp), intent(in) :: xp, yp
         integer(ip), intent(in) :: c1, c2, e1, e2
         integer(ip) :: q
         do q = 1, m
            if (hypot(px(q) - xp, py(q) - yp) <= g) then
               if (c1 > 0) then
                  pc1(q) = c1; pe1(q) = 0
               else if (pc1(q) == 0 .and. e1 > 0) then
                  pe1(q) = e1
               end if
               if (c2 > 0) then
                  pc2(q) = c2; pe2(q) = 0
               else if (pc2(q) == 0 .and. e2 > 0) then
                  pe2(q) = e2
               end if
               return
            end if
         end do
         m = m + 1
         px(m) = xp; py(m) = yp; plen(m) = 0.0_wp
         pc1(m) = c1; pc2(m) = c2; pe1(m) = e1; pe2(m) = e2
      end subroutine register
      !> Half a shared stretch of edges e1 (block b1) and e2 (block b2) to
      !> the point at (xp, yp); of the two contacts of a filled re-entrant
      !> corner, to the one on that edge.
      subroutine add_length(xp, yp, l, e1, e2)
         real(wp), intent(in) :: xp, yp, l
         integer(ip), intent(in) :: e1, e2
         integer(ip) :: q
         do q = 1, m
            if (psplit(q)) then
               if (pe1(q) > 0 .and. pe1(q) /= e1) cycle
               if (pe2(q) > 0 .and. pe2(q) /= e2) cycle
            end if
            if (hypot(px(q) - xp, py(q) - yp) <= 2.0_wp*g) then
               plen(q) = plen(q) + l
               return
            end if
         end do
      end subroutine add_length
   end subroutine pair_contacts

   !> Unit normal of the edge starting at corner `c`: sign +1 outward
   !> (left of a clockwise edge), -1 into the block.
   subroutine edge_normal(geo, c, sgn, nx, ny)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: sgn
      real(wp), intent(out) :: nx, ny
      real(wp) :: dx, dy, l
      dx = geo%corners%x(geo%corners%next(c)) - geo%corners%x(c)
      dy = geo%corners%y(geo%corners%next(c)) - geo%corners%y(c)
      l = hypot(dx, dy)
      nx = -sgn*dy/l
      ny = sgn*dx/l
   end subroutine edge_normal

   !> Outward bisector at corner `c`.
   subroutine corner_outward(geo, c, nx, ny)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(out) :: nx, ny
      real(wp) :: ax, ay, bx, by, l
      call edge_normal(geo, geo%corners%prev(c), 1.0_wp, ax, ay)
      call edge_normal(geo, c, 1.0_wp, bx, by)
      l = hypot(ax + bx, ay + by)
      if (l > 0.0_wp) then
         nx = (ax + bx)/l
         ny = (ay + by)/l
      else
         nx = ax
         ny = ay
      end if
   end subroutine corner_outward

end module contact_detection
