!> Contact update while blocks move (manual Section 3.3, SET DSCAN / UPCON):
!> new contacts are made where a corner comes within `margin` of another
!> block, contacts whose surfaces have separated by more than twice the
!> margin and carry no force are broken, and contact lengths are shared out
!> again. Existing contacts keep their id, material, constitutive number and
!> state (forces, displacements, flags); ids of broken contacts are not
!> reused, so an id printed by PRINT CONTACT names the same contact for as
!> long as it lives.
!>
!> A contact is identified by a corner and the block it touches: corner c of
!> block A against block B (kinds 2 and 3), or the pair of corners (kind 1,
!> which is the same contact as either corner against the other's block).
!> One exception: a corner that fills a re-entrant corner of the other block
!> (corner_fills_reflex: the plug of a TUNNEL at a vertex of the ring) touches
!> both of its edges and has one contact with each, keyed by the corner and
!> the edge; each takes the half-spacing on its own edge's side only
!> (contact_lengths below).
!> The broad phase is the bin grid of contact_broadphase, so a scan costs
!> O(blocks + contacts).
!>
!> Properties of a new contact: JMAT and JCONS of the nearest contact that
!> already joined the same two blocks (so a contact made on a joint given
!> its properties by CHANGE, e.g. at a gridpoint of a deformable edge, gets
!> that joint's properties), else of the nearest broken contact of the two
!> blocks (they separated and touch again); the defaults (SET JMATDF /
!> JCONDF, block material) only for a pair of blocks that never had a
!> contact. A new JCONS 5 contact keeps the fracture flag of the nearest
!> earlier contact of the pair, live or broken (a fractured joint that
!> opened and closed again has no cohesion or tension).
!>
!> A corner is not given a new contact where a contact of the same block
!> pair already touches (within a tenth of the margin): two rounded corners
!> at the end of a joint make one contact, whatever its current kind.
!>
!> Contact length (Fig 3-3b): contacts of one block pair lying along one
!> line (normals within 10 degrees, offsets within the margin) share the
!> stretch between them: each gets half the distance to its neighbour on
!> each side, measured between the contacts' corner vertices (not the
!> contact points, which lie a rounding radius inside the corners). An
!> isolated contact has length 0; the joint laws then use the minimum
!> contact length (SET CLEMIN). The two contacts of a corner in a filled
!> re-entrant corner share one vertex: each counts only the neighbour along
!> its own edge, so the two stretches are counted once each.
module contact_update
   use core_sort, only: sort_order, counts_to_starts
   use core_union_find, only: union_find_root, union_find_join
   use core_kinds, only: wp, ip, i1, l1
   use model_geometry, only: contact_corner1, contact_corner2, contact_edge1, contact_edge2
   use model_geometry, only: geometry_t, geometry_add_contact, geometry_block_polygon, &
                             joint_state_value
   use geometry_polygon, only: polygon_boundary_distance
   use contact_broadphase, only: broadphase_pairs, update_bounding_boxes
   use contact_kinematics, only: contact_geometry, corner_nearest_feature, edge_frame, &
                                 corner_fills_reflex, edge_frames_compute, contact_geometry_all
   use contact_joint_law, only: state_fractured
   implicit none
   private
   public :: contact_scan, contact_lengths, contact_kill_orphans, contact_margin
   public :: contact_joint_chains, contact_settle_geometry, corner_anchor

contains

   !> Distance within which a corner and a block form a contact: the rounding
   !> length (never below 1e-6 of the model extent).
   pure real(wp) function contact_margin(geo) result(m)
      type(geometry_t), intent(in) :: geo
      m = max(geo%round, 1.0e-6_wp*geo%extent)
   end function contact_margin

   !> Kill contacts whose blocks or corners are gone (DELETE, cuts).
   subroutine contact_kill_orphans(geo, nkilled)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(out) :: nkilled
      integer(ip) :: c
      logical :: ok
      nkilled = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         ok = geo%blocks%live(geo%contacts%block1(c)) .and. geo%blocks%live(geo%contacts%block2(c))
         if (ok) ok = alive(geo%contacts%end1(c)) .and. alive(geo%contacts%end2(c))
         if (.not. ok) then
            geo%contacts%live(c) = .false.
            nkilled = nkilled + 1
         end if
      end do
      if (nkilled > 0) geo%domains_valid = .false.
   contains
      logical function alive(k)
         integer(ip), intent(in) :: k
         alive = .true.
         if (k > 0) alive = geo%corners%live(k)
      end function alive
   end subroutine contact_kill_orphans

   !> Find new contacts within `margin`, break separated ones, share out
   !> lengths. `nnew` and `nbroken` count what changed; `overlap`, the
   !> largest overlap (-gap) of a contact kept or made, 0 if none overlaps.
   !> `search` false (default true): the contacts there are only (orphans
   !> killed, normals and points, separated ones broken, lengths, bounding
   !> boxes), without the search for new ones (broad phase and
   !> corners_against, three quarters of a scan): a CYCLE whose blocks have
   !> not travelled a quarter of the margin since the last search, with no
   !> command between that could change the contacts (engine_cycle,
   !> search_skippable). It leaves the contacts as the whole scan would
   !> whenever the search would have made none.
   !> `changed` (one flag a block): the search looks only at the pairs of the
   !> broad phase with a changed block (geometry_refresh after a cut on a
   !> cycled model: the blocks the cut made or re-ringed and those whose
   !> rounding it changed; issue 23). The pairs kept in the broad phase's
   !> order, the contacts made are, in the same order, those the search over
   !> every pair makes whenever no pair of unchanged blocks would make one.
   subroutine contact_scan(geo, margin, nnew, nbroken, overlap, search, changed)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: margin
      integer(ip), intent(out) :: nnew, nbroken
      real(wp), intent(out), optional :: overlap
      logical, intent(in), optional :: search
      logical, intent(in), optional :: changed(:)
      integer(ip) :: npair, k, c, nk, ncorner, kc1, kc2
      integer(ip), allocatable :: pa(:), pb(:), kfirst(:), kcont(:), kfill(:)
      integer(ip), allocatable :: bfirst(:), bcont(:), dfirst(:), dcont(:)
      real(wp) :: gap, nx, ny, px, py, ovmax
      logical :: find
      find = .true.
      if (present(search)) find = search
      ovmax = 0.0_wp
      nnew = 0
      call contact_kill_orphans(geo, nbroken)
      ! break contacts that have separated and carry no force
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         call contact_geometry(geo, c, 1.0e-3_wp*margin, gap, nx, ny, px, py)
         ! normal and point as the kind now stands (contact_lengths, occupied)
         geo%contacts%nx(c) = nx
         geo%contacts%ny(c) = ny
         geo%contacts%x(c) = px
         geo%contacts%y(c) = py
         ! (less the dilation ridden up, which the joint's asperities fill)
         if (gap - joint_state_value(geo%contacts%state%ud, c) > 2.0_wp*margin .and. &
             geo%contacts%state%fn(c) == 0.0_wp) then
            geo%contacts%live(c) = .false.
            nbroken = nbroken + 1
         else if (.not. (-gap <= ovmax)) then      ! also a NaN
            ovmax = -gap
         end if
      end do
      call drop_twins(geo, nbroken)
      call update_bounding_boxes(geo)
      if (find) call search_new()
      if (nnew > 0 .or. nbroken > 0) geo%domains_valid = .false.
      call contact_lengths(geo, margin)
      if (present(overlap)) overlap = ovmax
   contains
      !> The search for new contacts: the (corner, other block) keys that
      !> exist, the contacts of each block, then every corner of each pair of
      !> blocks of the broad phase against the other block.
      subroutine search_new()
         ! which (corner, other block) keys exist: CSR over corners of the
         ! contacts of each corner
         ncorner = geo%corners%n
         allocate (kfirst(ncorner + 1), kfill(ncorner))
         kfirst = 0
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            ! contact_corner1 and contact_corner2 without the calls (a scan
            ! passes every contact twice)
            kc1 = merge(0_ip, geo%contacts%end1(c), geo%contacts%kind(c) == 3_i1)
            kc2 = merge(0_ip, geo%contacts%end2(c), geo%contacts%kind(c) == 2_i1)
            if (kc1 > 0) kfirst(kc1 + 1) = kfirst(kc1 + 1) + 1
            if (kc2 > 0) kfirst(kc2 + 1) = kfirst(kc2 + 1) + 1
         end do
         call counts_to_starts(kfirst)
         allocate (kcont(max(1_ip, kfirst(ncorner + 1) - 1)))
         kfill = kfirst(1:ncorner)
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            kc1 = merge(0_ip, geo%contacts%end1(c), geo%contacts%kind(c) == 3_i1)
            kc2 = merge(0_ip, geo%contacts%end2(c), geo%contacts%kind(c) == 2_i1)
            if (kc1 > 0) then
               kcont(kfill(kc1)) = c
               kfill(kc1) = kfill(kc1) + 1
            end if
            if (kc2 > 0) then
               kcont(kfill(kc2)) = c
               kfill(kc2) = kfill(kc2) + 1
            end if
         end do
         nk = geo%contacts%n
         call contacts_by_block()
         call broadphase_pairs(geo, margin, npair, pa, pb)
         do k = 1, npair
            if (present(changed)) then
               if (.not. (changed(pa(k)) .or. changed(pb(k)))) cycle
            end if
            call corners_against(pa(k), pb(k))
            call corners_against(pb(k), pa(k))
         end do
      end subroutine search_new
      !> Corners of block ba against block bb.
      subroutine corners_against(ba, bb)
         integer(ip), intent(in) :: ba, bb
         integer(ip) :: cc, j, fid, r
         integer :: fkind
         real(wp) :: g, qx, qy
         cc = geo%blocks%first_corner(ba)
         do j = 1, geo%blocks%ncorner(ba)
            call corner_nearest_feature(geo, cc, bb, fkind, fid, g)
            if (fkind > 0 .and. g < margin .and. g > -margin) then
               r = filled_reflex(cc, fkind, fid)
               if (r > 0) then
                  ! in a re-entrant corner r of bb: a contact with each edge
                  call edge_contact(cc, ba, bb, geo%corners%prev(r))
                  call edge_contact(cc, ba, bb, r)
               else if (.not. (has_key(cc, bb) .or. (fkind == 1 .and. has_key(fid, ba)))) then
                  call touch_point(cc, fkind, fid, g, qx, qy)
                  if (.not. (made_now(cc, bb, fkind, fid) .or. &
                             occupied(min(ba, bb), max(ba, bb), qx, qy))) &
                     call make_contact(cc, ba, bb, fkind, fid)
               end if
            end if
            cc = geo%corners%next(cc)
         end do
      end subroutine corners_against
      !> The re-entrant corner of block bb that corner cc fills
      !> (corner_fills_reflex), found from cc's nearest feature of bb (an edge
      !> at either end, or the corner itself); 0 if none.
      integer(ip) function filled_reflex(cc, fkind, fid) result(r)
         integer(ip), intent(in) :: cc, fid
         integer, intent(in) :: fkind
         r = 0
         if (corner_fills_reflex(geo, cc, fid, margin)) then
            r = fid
         else if (fkind == 2) then
            if (corner_fills_reflex(geo, cc, geo%corners%next(fid), margin)) r = geo%corners%next(fid)
         end if
      end function filled_reflex
      !> Contact of corner cc (block ba) with edge e (block bb), unless the
      !> corner already has one with that edge or another contact of the
      !> two blocks touches where it would.
      subroutine edge_contact(cc, ba, bb, e)
         integer(ip), intent(in) :: cc, ba, bb, e
         integer(ip) :: q, c
         real(wp) :: ux, uy, ex, ey, s0, s1, g, qx, qy
         if (cc <= ncorner) then
            do q = kfirst(cc), kfirst(cc + 1) - 1
               if (on_edge(kcont(q), cc, e)) return
            end do
         end if
         do c = nk + 1, geo%contacts%n
            if (on_edge(c, cc, e)) return
         end do
         call edge_frame(geo, e, ux, uy, ex, ey, s0, s1)
         g = (geo%corners%rx(cc) - geo%corners%x(e))*ex + (geo%corners%ry(cc) - geo%corners%y(e))*ey &
             - geo%corners%radius(cc)
         call touch_point(cc, 2, e, g, qx, qy)
         if (occupied(min(ba, bb), max(ba, bb), qx, qy)) return
         call make_contact(cc, ba, bb, 2, e)
      end subroutine edge_contact
      !> Contact c is corner cc against edge e.
      logical function on_edge(c, cc, e)
         integer(ip), intent(in) :: c, cc, e
         associate (ct => geo%contacts)
            on_edge = ct%live(c) .and. ((ct%kind(c) == 2 .and. contact_corner1(ct, c) == cc .and. &
                                          contact_edge2(ct, c) == e) .or. &
                                         (ct%kind(c) == 3 .and. contact_corner2(ct, c) == cc .and. &
                                          contact_edge1(ct, c) == e))
         end associate
      end function on_edge
      !> New contact of corner cc (block ba) with feature fid of block bb
      !> (fkind 1 a corner, 2 an edge).
      subroutine make_contact(cc, ba, bb, fkind, fid)
         integer(ip), intent(in) :: cc, ba, bb, fid
         integer, intent(in) :: fkind
         integer(ip) :: cnew, b1, b2
         call geometry_add_contact(geo, cnew)
         nnew = nnew + 1
         b1 = min(ba, bb)
         b2 = max(ba, bb)
         geo%contacts%block1(cnew) = b1
         geo%contacts%block2(cnew) = b2
         if (fkind == 1) then
            geo%contacts%kind(cnew) = 1
            if (ba == b1) then
               geo%contacts%end1(cnew) = cc; geo%contacts%end2(cnew) = fid
            else
               geo%contacts%end1(cnew) = fid; geo%contacts%end2(cnew) = cc
            end if
         else if (ba == b1) then
            geo%contacts%kind(cnew) = 2
            geo%contacts%end1(cnew) = cc; geo%contacts%end2(cnew) = fid
         else
            geo%contacts%kind(cnew) = 3
            geo%contacts%end1(cnew) = fid; geo%contacts%end2(cnew) = cc
         end if
         geo%contacts%jcons(cnew) = int(geo%jcons_default, i1)
         geo%contacts%jmat(cnew) = merge(geo%jmat_default, &
                                         geo%blocks%material(b1), geo%jmat_default > 0)
         call contact_geometry(geo, cnew, 1.0e-3_wp*margin, gap, nx, ny, px, py)
         call inherit(cnew, b1, b2, px, py, nx, ny, gap)
         geo%contacts%gap(cnew) = gap
         if (.not. (-gap <= ovmax)) ovmax = -gap
         geo%contacts%nx(cnew) = nx
         geo%contacts%ny(cnew) = ny
         geo%contacts%x(cnew) = px
         geo%contacts%y(cnew) = py
      end subroutine make_contact
      !> Where the circle of corner `cc` touches the feature found by
      !> corner_nearest_feature (`fkind`, `fid`, gap `g`): the point halfway
      !> across the gap, as contact_geometry places it.
      subroutine touch_point(cc, fkind, fid, g, qx, qy)
         integer(ip), intent(in) :: cc, fid
         integer, intent(in) :: fkind
         real(wp), intent(in) :: g
         real(wp), intent(out) :: qx, qy
         real(wp) :: ux, uy, ex, ey, s0, s1, d
         associate (co => geo%corners)
            if (fkind == 2) then
               call edge_frame(geo, fid, ux, uy, ex, ey, s0, s1)
               qx = co%rx(cc) - ex*(co%radius(cc) + 0.5_wp*g)
               qy = co%ry(cc) - ey*(co%radius(cc) + 0.5_wp*g)
            else
               ex = co%rx(fid) - co%rx(cc)
               ey = co%ry(fid) - co%ry(cc)
               d = hypot(ex, ey)
               qx = co%rx(cc)
               qy = co%ry(cc)
               if (d > 0.0_wp) then
                  qx = qx + ex/d*(co%radius(cc) + 0.5_wp*g)
                  qy = qy + ey/d*(co%radius(cc) + 0.5_wp*g)
               end if
            end if
         end associate
      end subroutine touch_point
      !> A live contact of blocks b1 < b2 already touches at (qx, qy) (within
      !> a tenth of the margin). Two rounded corners meeting at the end of a
      !> joint make ONE contact; once the blocks shear a little it switches
      !> from corner-corner to one corner against the other block's edge
      !> (contact_geometry) and the corner it let go must not get a second
      !> contact at the same point: that one would start force-free and take
      !> the whole stiffness of the shared length (contact_lengths), leaving
      !> the old contact's force on the minimum length, so the joint end
      !> would respond differently on loading and unloading.
      logical function occupied(b1, b2, qx, qy)
         integer(ip), intent(in) :: b1, b2
         real(wp), intent(in) :: qx, qy
         integer(ip) :: q, c
         real(wp) :: tol
         tol = 0.1_wp*margin
         occupied = .true.
         do q = bfirst(b1), bfirst(b1 + 1) - 1
            c = bcont(q)
            if (geo%contacts%block2(c) /= b2 .or. .not. geo%contacts%live(c)) cycle
            if (hypot(geo%contacts%x(c) - qx, geo%contacts%y(c) - qy) <= tol) return
         end do
         do c = nk + 1, geo%contacts%n
            if (geo%contacts%block1(c) /= b1 .or. geo%contacts%block2(c) /= b2) cycle
            if (hypot(geo%contacts%x(c) - qx, geo%contacts%y(c) - qy) <= tol) return
         end do
         occupied = .false.
      end function occupied
      !> Existing live contacts of every block (CSR), for `inherit` and
      !> `occupied`; and the broken ones between two live blocks (dfirst,
      !> dcont), for `inherit`.
      subroutine contacts_by_block()
         call by_block(.true., bfirst, bcont)
         call by_block(.false., dfirst, dcont)
      end subroutine contacts_by_block
      subroutine by_block(alive, first, list)
         logical, intent(in) :: alive
         integer(ip), allocatable, intent(out) :: first(:), list(:)
         integer(ip), allocatable :: fill(:)
         integer(ip) :: q, b
         allocate (first(geo%blocks%n + 1), fill(geo%blocks%n))
         first = 0
         do q = 1, nk
            if (.not. wanted(q, alive)) cycle
            b = geo%contacts%block1(q)
            first(b + 1) = first(b + 1) + 1
         end do
         call counts_to_starts(first)
         allocate (list(max(1_ip, first(geo%blocks%n + 1) - 1)))
         fill = first(1:geo%blocks%n)
         do q = 1, nk
            if (.not. wanted(q, alive)) cycle
            b = geo%contacts%block1(q)
            list(fill(b)) = q
            fill(b) = fill(b) + 1
         end do
      end subroutine by_block
      !> Contact q for by_block: live (alive), or broken between two live
      !> blocks.
      logical function wanted(q, alive)
         integer(ip), intent(in) :: q
         logical, intent(in) :: alive
         integer(ip) :: b1, b2
         if (alive) then
            wanted = geo%contacts%live(q)
            return
         end if
         wanted = .false.
         if (geo%contacts%live(q)) return
         b1 = geo%contacts%block1(q)
         b2 = geo%contacts%block2(q)
         if (b1 < 1 .or. b2 < 1 .or. b1 > geo%blocks%n .or. b2 > geo%blocks%n) return
         wanted = geo%blocks%live(b1) .and. geo%blocks%live(b2)
      end function wanted
      !> JMAT / JCONS of the nearest earlier contact between b1 and b2: a
      !> live one, else one that was broken (the blocks had separated; their
      !> joint keeps the properties CHANGE gave it). A JCONS 5 contact
      !> takes the fracture flag of the nearest earlier contact of the pair,
      !> live or broken: the manual's flag is the joint segment's (Section
      !> 4.5, CHANGE JCONS 5), and a joint that fractured, opened and
      !> closed again stays without cohesion and tension.
      !> The dilation ridden up (state%ud) is taken from that nearest
      !> contact too when both lie on one joint plane (normals within about
      !> 8 degrees) and the new contact is no further open than that
      !> dilation: a block riding up a dilatant joint whose corner passes the
      !> end of the other block's edge makes a new contact on the same
      !> asperities (probe_rigid_decks, dilation), where a fresh ud = 0
      !> would see the joint open by the whole dilation and drop the block.
      subroutine inherit(cnew, b1, b2, px, py, nx, ny, gap)
         integer(ip), intent(in) :: cnew, b1, b2
         real(wp), intent(in) :: px, py, nx, ny, gap
         integer(ip) :: best, dead
         real(wp) :: dbest, ddead
         call nearest(bfirst, bcont, b1, b2, px, py, best, dbest)
         call nearest(dfirst, dcont, b1, b2, px, py, dead, ddead)
         if (best > 0) then
            geo%contacts%jmat(cnew) = geo%contacts%jmat(best)
            geo%contacts%jcons(cnew) = geo%contacts%jcons(best)
         else if (dead > 0) then
            geo%contacts%jmat(cnew) = geo%contacts%jmat(dead)
            geo%contacts%jcons(cnew) = geo%contacts%jcons(dead)
         end if
         if (dead > 0 .and. ddead < dbest) best = dead
         if (best > 0 .and. allocated(geo%contacts%state%ud)) then
            if (nx*geo%contacts%nx(best) + ny*geo%contacts%ny(best) > 0.99_wp .and. &
                gap <= geo%contacts%state%ud(best) + margin) &
               geo%contacts%state%ud(cnew) = geo%contacts%state%ud(best)
         end if
         if (best == 0 .or. geo%contacts%jcons(cnew) /= 5) return
         if (iand(geo%contacts%state%flags(best), state_fractured) /= 0) &
            geo%contacts%state%flags(cnew) = ior(geo%contacts%state%flags(cnew), state_fractured)
      end subroutine inherit
      !> The contact of list(first(b1):first(b1+1)-1) between b1 and b2
      !> nearest to (px, py) (q = 0 if none), and its squared distance dq.
      subroutine nearest(first, list, b1, b2, px, py, q, dq)
         integer(ip), intent(in) :: first(:), list(:), b1, b2
         real(wp), intent(in) :: px, py
         integer(ip), intent(out) :: q
         real(wp), intent(out) :: dq
         integer(ip) :: i
         real(wp) :: d
         q = 0
         dq = huge(1.0_wp)
         do i = first(b1), first(b1 + 1) - 1
            if (geo%contacts%block2(list(i)) /= b2) cycle
            d = (geo%contacts%x(list(i)) - px)**2 + (geo%contacts%y(list(i)) - py)**2
            if (d < dq) then
               dq = d
               q = list(i)
            end if
         end do
      end subroutine nearest
      logical function has_key(corner, other)
         integer(ip), intent(in) :: corner, other
         integer(ip) :: q, c, ob
         has_key = .false.
         if (corner > ncorner) return
         do q = kfirst(corner), kfirst(corner + 1) - 1
            c = kcont(q)
            ob = geo%contacts%block2(c)
            ! (corner1 is end1 but for kind 3: contact_corner1 without the call)
            if (geo%contacts%end1(c) /= corner .or. geo%contacts%kind(c) == 3) &
               ob = geo%contacts%block1(c)
            if (ob == other) then
               has_key = .true.
               return
            end if
         end do
      end function has_key
      !> A contact made earlier in this scan with the same key.
      logical function made_now(corner, other, fkind, fid)
         integer(ip), intent(in) :: corner, other, fid
         integer, intent(in) :: fkind
         made_now = new_key(corner, other)
         if (.not. made_now .and. fkind == 1) made_now = new_key(fid, geo%corners%block(corner))
      end function made_now
      logical function new_key(corner, other)
         integer(ip), intent(in) :: corner, other
         integer(ip) :: q
         new_key = .false.
         do q = nk + 1, geo%contacts%n
            if ((contact_corner1(geo%contacts, q) == corner .and. &
                 geo%contacts%block2(q) == other) .or. &
                (contact_corner2(geo%contacts, q) == corner .and. &
                 geo%contacts%block1(q) == other)) then
               new_key = .true.
               return
            end if
         end do
      end function new_key
   end subroutine contact_scan

   !> Share contact lengths out along lines of contacts of the same pair.
   subroutine contact_lengths(geo, margin)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: margin
      call tributaries(geo, margin, geo%contacts%length)
   end subroutine contact_lengths

   !> The joints of INSITU: contacts linked by contact_lengths' neighbours
   !> (one block pair, along one line) form a chain that stands for one
   !> stretch of joint, the chord from the corner vertex of its first
   !> contact to that of its last. For each live contact c: the unit normal
   !> (jnx, jny) of its chain's chord, on the side of the contact normal
   !> (the normal of a contact between two rounded corners leans off the
   !> joint by the corners' offset), the length w(c) of chord it stands for
   !> (half the distance to each neighbour, measured along the chord, so
   !> that a chain's lengths add up to its chord) and that stretch's centre
   !> (cx, cy) on the chord, and the chain's two end contacts ends(1:2, c)
   !> (0 for a contact without neighbours: then w is its length, (cx, cy)
   !> its vertex). INSITU loads each chain with the traction on its chord,
   !> so that a rigid block whose edges are joints and boundary is in
   !> equilibrium under a uniform stress whatever its contact normals.
   subroutine contact_joint_chains(geo, margin, cx, cy, w, jnx, jny, ends)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: margin
      real(wp), allocatable, intent(out) :: cx(:), cy(:), w(:), jnx(:), jny(:)
      integer(ip), allocatable, intent(out) :: ends(:, :)
      real(wp), allocatable :: smin(:), smax(:), sc(:), ux(:), uy(:)
      integer(ip), allocatable :: nplus(:), nminus(:), root(:), member(:), rootm(:), order(:)
      logical, allocatable :: bent(:), twin(:)
      integer(ip) :: n, c, r, m, i, lo, hi
      real(wp) :: tx, ty, s, l, ax, ay, bx, by, left, right
      n = geo%contacts%n
      allocate (w(n), nplus(n), nminus(n), root(n), smin(n), smax(n), sc(n), ux(n), uy(n))
      allocate (jnx(n), jny(n), ends(2, n), bent(n))
      bent = .false.
      w = 0.0_wp
      call tributaries(geo, margin, w, cx, cy, nplus, nminus)
      do c = 1, n
         root(c) = c
      end do
      ! a chain is straight: contact_lengths' neighbours may lie on the
      ! next chord of a many-sided TUNNEL ring (chords 9 degrees apart)
      ! (a neighbour on another line means that the joint bends there: the
      ! contact ends its chain; contact_lengths may pick a neighbour within
      ! 10 degrees past a bend, e.g. where a joint meets a ring's chord
      ! near a vertex)
      call mark_twins()
      do c = 1, n
         if (.not. geo%contacts%live(c)) cycle
         if (nplus(c) > 0) then
            if (straight(c, nplus(c))) call union_find_join(root, c, nplus(c))
         end if
         if (nminus(c) > 0) then
            if (straight(c, nminus(c))) call union_find_join(root, c, nminus(c))
         end if
      end do
      ends = 0
      smin = huge(1.0_wp)
      smax = -huge(1.0_wp)
      ! the chain's ends: its extreme vertices along the tangent of its root
      do c = 1, n
         jnx(c) = geo%contacts%nx(c)
         jny(c) = geo%contacts%ny(c)
         if (.not. in_chain(c)) cycle
         r = union_find_root(root, c)
         tx = -geo%contacts%ny(r)
         ty = geo%contacts%nx(r)
         call corner_anchor(geo, c, ax, ay)
         s = ax*tx + ay*ty
         if (s < smin(r)) then
            smin(r) = s
            ends(1, r) = c
         end if
         if (s > smax(r)) then
            smax(r) = s
            ends(2, r) = c
         end if
      end do
      ! chord normal and each contact's place along the chord
      m = 0
      allocate (member(n))
      do c = 1, n
         if (.not. in_chain(c)) cycle
         r = union_find_root(root, c)
         ends(:, c) = ends(:, r)
         if (ends(1, r) == 0 .or. ends(2, r) == 0 .or. ends(1, r) == ends(2, r)) cycle
         call corner_anchor(geo, ends(1, r), ax, ay)
         call corner_anchor(geo, ends(2, r), bx, by)
         l = hypot(bx - ax, by - ay)
         if (.not. (l > 0.0_wp)) cycle
         ux(c) = (bx - ax)/l
         uy(c) = (by - ay)/l
         jnx(c) = -uy(c)
         jny(c) = ux(c)
         if (jnx(c)*geo%contacts%nx(c) + jny(c)*geo%contacts%ny(c) < 0.0_wp) then
            jnx(c) = -jnx(c)
            jny(c) = -jny(c)
         end if
         call corner_anchor(geo, c, bx, by)
         sc(c) = (bx - ax)*ux(c) + (by - ay)*uy(c)
         ! every vertex on the chord, or the chain is not one joint
         if (abs((bx - ax)*uy(c) - (by - ay)*ux(c)) > 1.0e-2_wp*l) bent(r) = .true.
         m = m + 1
         member(m) = c
      end do
      call strips()
      ! a bent chain: its contacts keep their own stretches and normals
      i = 0
      do lo = 1, m
         c = member(lo)
         if (bent(union_find_root(root, c))) then
            ends(:, c) = 0
            jnx(c) = geo%contacts%nx(c)
            jny(c) = geo%contacts%ny(c)
         else
            i = i + 1
            member(i) = c
         end if
      end do
      m = i
      if (m == 0) return
      ! members in order of chain, then of place along the chord
      allocate (order(m))
      call sort_order(sc(member(1:m)), order)
      member(1:m) = member(order)
      allocate (rootm(m))
      do i = 1, m
         rootm(i) = union_find_root(root, member(i))
      end do
      call sort_order(rootm, order)
      member(1:m) = member(order)
      rootm = rootm(order)
      lo = 1
      do while (lo <= m)
         hi = lo
         do while (hi < m)
            if (rootm(hi + 1) /= rootm(lo)) exit
            hi = hi + 1
         end do
         do i = lo, hi
            c = member(i)
            left = sc(c)
            right = sc(c)
            if (i > lo) left = 0.5_wp*(sc(member(i - 1)) + sc(c))
            if (i < hi) right = 0.5_wp*(sc(c) + sc(member(i + 1)))
            w(c) = right - left
            call corner_anchor(geo, ends(1, c), ax, ay)
            cx(c) = ax + 0.5_wp*(left + right)*ux(c)
            cy(c) = ay + 0.5_wp*(left + right)*uy(c)
         end do
         lo = hi + 1
      end do
   contains
      !> A joint strip shorter than two rounding lengths: two corners of
      !> blocks A and B lie on one joint, each on the other block's edge,
      !> closer than 2 ROUND. Each corner's rounding centre then falls past
      !> the straight part of the other's edge, so both corner-edge contacts
      !> become one corner-corner contact of the same two corners (twins;
      !> the first step's drop_twins keeps the lower id). Its anchor is the
      !> vertices' mean, its normal joins the rounding centres, and it has
      !> no neighbour: it stood for no joint at all (w = 0), and the strip's
      !> load was missing from both blocks (3.56 cm at 11 MPa: 3.9e5 N;
      !> random tunnel genu 23; zoned blocks moved 2.2e-5 m). Such a
      !> contact (kind 1, not in a chain, its vertices apart along an edge
      !> of each corner) stands for the strip between the two vertices: w
      !> their distance, the normal that of the strip, the centre its
      !> middle; a twin of it takes nothing.
      subroutine strips()
         integer(ip) :: c, d, k1, k2
         real(wp) :: x1, y1, x2, y2, vx, vy, l
         do c = 1, n
            if (.not. geo%contacts%live(c)) cycle
            if (geo%contacts%kind(c) /= 1 .or. in_chain(c)) cycle
            k1 = contact_corner1(geo%contacts, c)
            k2 = contact_corner2(geo%contacts, c)
            x1 = geo%corners%x(k1)
            y1 = geo%corners%y(k1)
            x2 = geo%corners%x(k2)
            y2 = geo%corners%y(k2)
            vx = x2 - x1
            vy = y2 - y1
            l = hypot(vx, vy)
            if (.not. (l > 1.0e-3_wp*margin)) cycle
            if (.not. (corner_along(k1, vx, vy, 1.0e-2_wp*l) .and. &
                       corner_along(k2, vx, vy, 1.0e-2_wp*l))) cycle
            ! a twin with a lower id takes the strip
            do d = 1, c - 1
               if (.not. geo%contacts%live(d)) cycle
               if (geo%contacts%kind(d) == 1 .and. contact_corner1(geo%contacts, d) == k1 .and. &
                   contact_corner2(geo%contacts, d) == k2) exit
            end do
            if (d < c) then
               w(c) = 0.0_wp
               cycle
            end if
            w(c) = l
            cx(c) = 0.5_wp*(x1 + x2)
            cy(c) = 0.5_wp*(y1 + y2)
            jnx(c) = -vy/l
            jny(c) = vx/l
            if (jnx(c)*geo%contacts%nx(c) + jny(c)*geo%contacts%ny(c) < 0.0_wp) then
               jnx(c) = -jnx(c)
               jny(c) = -jny(c)
            end if
         end do
      end subroutine strips
      !> Do the vertices of contacts c and d lie on one line along an edge
      !> of each of them (the edge a corner touches; for two corners, an
      !> edge of either)?
      logical function straight(c, d)
         integer(ip), intent(in) :: c, d
         real(wp) :: ax, ay, bx, by, vx, vy, tol
         call corner_anchor(geo, c, ax, ay)
         call corner_anchor(geo, d, bx, by)
         vx = bx - ax
         vy = by - ay
         tol = 1.0e-2_wp*hypot(vx, vy)
         straight = along(c, vx, vy, tol) .and. along(d, vx, vy, tol)
      end function straight
      logical function along(c, vx, vy, tol)
         integer(ip), intent(in) :: c
         real(wp), intent(in) :: vx, vy, tol
         associate (ct => geo%contacts)
            along = .false.
            select case (ct%kind(c))
            case (1)
               along = corner_along(contact_corner1(ct, c), vx, vy, tol) .or. &
                       corner_along(contact_corner2(ct, c), vx, vy, tol)
            case (2)
               ! a corner on an edge: along that edge or its own (not for
               ! the corner of a filled re-entrant corner: it has a contact
               ! on each edge there, both at its vertex)
               along = edge_along(contact_edge2(ct, c), vx, vy, tol)
               if (.not. twin(c)) along = along .or. &
                                          corner_along(contact_corner1(ct, c), vx, vy, tol)
            case (3)
               along = edge_along(contact_edge1(ct, c), vx, vy, tol)
               if (.not. twin(c)) along = along .or. &
                                          corner_along(contact_corner2(ct, c), vx, vy, tol)
            end select
         end associate
      end function along
      !> twin(c): contact c is a corner against an edge (kind 2 or 3) and
      !> the same corner has another such contact with the same block.
      subroutine mark_twins()
         integer(ip), allocatable :: head(:), nxt(:)
         integer(ip) :: a, b, k
         allocate (twin(n), nxt(n), head(max(1_ip, geo%corners%n)))
         twin = .false.
         head = 0
         nxt = 0
         do a = 1, n
            k = own_corner(a)
            if (k <= 0) cycle
            b = head(k)
            do while (b > 0)
               if (geo%contacts%block1(b) == geo%contacts%block1(a) .and. &
                   geo%contacts%block2(b) == geo%contacts%block2(a)) then
                  twin(a) = .true.
                  twin(b) = .true.
               end if
               b = nxt(b)
            end do
            nxt(a) = head(k)
            head(k) = a
         end do
      end subroutine mark_twins
      integer(ip) function own_corner(c)
         integer(ip), intent(in) :: c
         own_corner = 0
         if (.not. geo%contacts%live(c)) return
         if (geo%contacts%kind(c) == 2) own_corner = contact_corner1(geo%contacts, c)
         if (geo%contacts%kind(c) == 3) own_corner = contact_corner2(geo%contacts, c)
      end function own_corner
      logical function corner_along(k, vx, vy, tol)
         integer(ip), intent(in) :: k
         real(wp), intent(in) :: vx, vy, tol
         corner_along = .false.
         if (k <= 0) return
         corner_along = edge_along(k, vx, vy, tol) .or. edge_along(geo%corners%prev(k), vx, vy, tol)
      end function corner_along
      logical function edge_along(e, vx, vy, tol)
         integer(ip), intent(in) :: e
         real(wp), intent(in) :: vx, vy, tol
         real(wp) :: ux, uy, l
         integer(ip) :: q
         edge_along = .false.
         if (e <= 0) return
         q = geo%corners%next(e)
         ux = geo%corners%x(q) - geo%corners%x(e)
         uy = geo%corners%y(q) - geo%corners%y(e)
         l = hypot(ux, uy)
         if (.not. (l > 0.0_wp)) return
         edge_along = abs(vx*uy - vy*ux)/l <= tol
      end function edge_along
      logical function in_chain(c)
         integer(ip), intent(in) :: c
         in_chain = geo%contacts%live(c)
         if (in_chain) in_chain = nplus(c) > 0 .or. nminus(c) > 0
         ! zoned blocks: their gridpoints take each contact's force on its
         ! own stretch (no chains)
         if (in_chain) in_chain = .not. (geo%blocks%fdef(geo%contacts%block1(c)) .or. &
                                         geo%blocks%fdef(geo%contacts%block2(c)))
      end function in_chain
   end subroutine contact_joint_chains

   !> The contact points, normals, kinds and gaps the first step of CYCLE
   !> gives (the pass of contact_geometry_pass): INSITU sets the forces in
   !> these frames, so that the first step neither turns them nor sees a
   !> normal increment (the gap of contact_scan and that of the pass differ
   !> by round-off: 1e-11 m, 0.15 N on a 1e10 Pa/m joint).
   subroutine contact_settle_geometry(geo, margin)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: margin
      real(wp), allocatable :: frame(:, :), gap_new(:)
      logical(l1), allocatable :: void(:)
      integer(ip) :: bad
      if (geo%contacts%n == 0) return
      allocate (frame(4, max(16_ip, geo%corners%n)), gap_new(geo%contacts%n))
      allocate (void(geo%contacts%n))
      void = .true._l1      ! every gap is taken as it stands
      call edge_frames_compute(geo, frame)
      call contact_geometry_all(geo, 1.0e-3_wp*margin, frame, void, huge(1.0_wp), gap_new, bad)
   end subroutine contact_settle_geometry

   !> Lengths and stretch centres of contact_lengths / contact_tributary_centres
   !> (the centres only where asked for: contact_lengths runs at the start of
   !> every CYCLE, where its temporaries made the run's peak memory, issue 23).
   subroutine tributaries(geo, margin, length, cx, cy, nplus, nminus)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: margin
      real(wp), intent(inout) :: length(:)
      real(wp), allocatable, intent(out), optional :: cx(:), cy(:)
      integer(ip), intent(out), optional :: nplus(:), nminus(:)
      integer(ip) :: n, i, j, c, d, lo, hi, b1, b2
      integer(ip), allocatable :: idx(:)
      real(wp), allocatable :: ax(:), ay(:)
      real(wp) :: tx, ty, s, dplus, dminus, off, side
      real(wp), allocatable :: p1x(:), p1y(:), p2x(:), p2y(:)
      integer(ip) :: jplus, jminus
      real(wp), parameter :: cos_tol = 0.98480775301220802_wp   ! cos(10 degrees)
      logical :: centres
      centres = present(cx) .and. present(cy)
      allocate (ax(max(1_ip, geo%contacts%n)), ay(max(1_ip, geo%contacts%n)))
      if (centres) then
         allocate (cx(geo%contacts%n), cy(geo%contacts%n))
         cx = 0.0_wp
         cy = 0.0_wp
      end if
      if (present(nplus)) nplus = 0
      if (present(nminus)) nminus = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         call corner_anchor(geo, c, ax(c), ay(c))
         if (centres) then
            cx(c) = ax(c)
            cy(c) = ay(c)
         end if
      end do
      call pair_order(geo, idx, n)
      if (n == 0) return
      lo = 1
      do while (lo <= n)
         b1 = geo%contacts%block1(idx(lo))
         b2 = geo%contacts%block2(idx(lo))
         hi = lo
         do while (hi < n)
            if (geo%contacts%block1(idx(hi + 1)) /= b1 .or. geo%contacts%block2(idx(hi + 1)) /= b2) exit
            hi = hi + 1
         end do
         ! the two blocks' outlines: a neighbour counts only across a stretch
         ! both blocks share (below)
         call geometry_block_polygon(geo, b1, p1x, p1y)
         call geometry_block_polygon(geo, b2, p2x, p2y)
         do i = lo, hi
            c = idx(i)
            tx = -geo%contacts%ny(c)
            ty = geo%contacts%nx(c)
            dplus = huge(1.0_wp)
            dminus = huge(1.0_wp)
            jplus = 0
            jminus = 0
            side = own_side(c, lo, hi, tx, ty)
            do j = lo, hi
               d = idx(j)
               if (d == c) cycle
               if (geo%contacts%nx(c)*geo%contacts%nx(d) + geo%contacts%ny(c)*geo%contacts%ny(d) &
                   < cos_tol) cycle
               s = (ax(d) - ax(c))*tx + (ay(d) - ay(c))*ty
               ! one of the two contacts of a filled re-entrant corner: only
               ! along its own edge
               if (s*side < 0.0_wp) cycle
               ! d on c's line or c on d's: the same test from either side. At a
               ! joint's slight bend one contact's tangent passes its far
               ! neighbour by nearly the margin; the one-sided test let 10 take
               ! 8 as its neighbour and not 8 take 10, and the pair's lengths
               ! lost a stretch (quick random tunnel 190: 0.67 degrees over
               ! 16.6 m, 0.193 m off against ROUND 0.1945; contact 8's length
               ! fell from 12.46 to 4.04 m at the first CYCLE, under the force
               ! INSITU gave 12.46 m of joint)
               off = min(abs((ax(d) - ax(c))*geo%contacts%nx(c) + (ay(d) - ay(c))*geo%contacts%ny(c)), &
                         abs((ax(d) - ax(c))*geo%contacts%nx(d) + (ay(d) - ay(c))*geo%contacts%ny(d)))
               if (off > margin) cycle
               if (s > 0.0_wp .and. s < dplus) then
                  dplus = s
                  jplus = d
               end if
               if (s < 0.0_wp .and. -s < dminus) then
                  dminus = -s
                  jminus = d
               end if
            end do
            ! Two blocks may share two joints on one line with a gap between
            ! (the halves of a block cut by TUNNEL's key cuts, on either side
            ! of the opening): the nearest contact beyond the gap is not a
            ! neighbour. Found on a new user's tunnel: the mouth contact at
            ! the wall took half the tunnel's width as its length, 1.6 m for
            ! 0.1 m, and its stiffness blew the model up at cycle 4.
            if (jplus > 0) then
               if (.not. shared(c, jplus)) dplus = huge(1.0_wp)
            end if
            if (jminus > 0) then
               if (.not. shared(c, jminus)) dminus = huge(1.0_wp)
            end if
            length(c) = 0.0_wp
            s = 0.0_wp     ! offset of the stretch centre along t
            if (present(nplus) .and. dplus < huge(1.0_wp)) nplus(c) = jplus
            if (present(nminus) .and. dminus < huge(1.0_wp)) nminus(c) = jminus
            if (dplus < huge(1.0_wp)) then
               length(c) = length(c) + 0.5_wp*dplus
               s = s + 0.25_wp*dplus
            end if
            if (dminus < huge(1.0_wp)) then
               length(c) = length(c) + 0.5_wp*dminus
               s = s - 0.25_wp*dminus
            end if
            if (centres) then
               cx(c) = ax(c) + s*tx
               cy(c) = ay(c) + s*ty
            end if
         end do
         lo = hi + 1
      end do
   contains
      !> 0 for most contacts. For one of the two contacts of a corner in a
      !> filled re-entrant corner (the same corner against the two edges
      !> meeting at a vertex r of the other block, contacts idx(lo:hi) being
      !> those of the block pair): +1 if its edge runs from r along the
      !> tangent (tx, ty), -1 if against it. Its stretch is on that side.
      real(wp) function own_side(c, lo, hi, tx, ty) result(side)
         integer(ip), intent(in) :: c, lo, hi
         real(wp), intent(in) :: tx, ty
         integer(ip) :: j, d, cc, dc, e, f
         real(wp) :: ux, uy, ex, ey, s0, s1
         side = 0.0_wp
         if (.not. corner_edge(c, cc, e)) return
         do j = lo, hi
            d = idx(j)
            if (d == c) cycle
            if (.not. corner_edge(d, dc, f)) cycle
            if (dc /= cc) cycle
            call edge_frame(geo, e, ux, uy, ex, ey, s0, s1)
            if (geo%corners%next(f) == e) then
               ! r is the start of edge e: the stretch runs along e
               side = sign(1.0_wp, ux*tx + uy*ty)
               return
            else if (geo%corners%next(e) == f) then
               ! r is the end of edge e: the stretch runs back along e
               side = -sign(1.0_wp, ux*tx + uy*ty)
               return
            end if
         end do
      end function own_side
      !> Contact c is a corner `cc` against an edge `e` (kind 2 or 3).
      logical function corner_edge(c, cc, e)
         integer(ip), intent(in) :: c
         integer(ip), intent(out) :: cc, e
         corner_edge = .true.
         select case (geo%contacts%kind(c))
         case (2)
            cc = geo%contacts%end1(c); e = geo%contacts%end2(c)
         case (3)
            cc = geo%contacts%end2(c); e = geo%contacts%end1(c)
         case default
            corner_edge = .false.
            cc = 0; e = 0
         end select
      end function corner_edge
      !> Is the midpoint between the anchors of contacts c and d on the
      !> outline of both blocks (within the contact margin, plus the larger
      !> of the two contacts' gaps: an opened joint's anchors lie on either
      !> face, the midpoint between them)?
      logical function shared(c, d)
         integer(ip), intent(in) :: c, d
         real(wp) :: mx, my, tolb
         mx = 0.5_wp*(ax(c) + ax(d))
         my = 0.5_wp*(ay(c) + ay(d))
         tolb = margin + max(abs(geo%contacts%gap(c)), abs(geo%contacts%gap(d)))
         shared = polygon_boundary_distance(p1x, p1y, mx, my) <= tolb .and. &
                  polygon_boundary_distance(p2x, p2y, mx, my) <= tolb
      end function shared
   end subroutine tributaries

   !> The live contacts idx(1:n) ordered by (block1, block2), those of one
   !> pair in contact order: a stable bucket sort by block1, then each
   !> bucket (the few contacts of one block) by block2 in place, stably.
   !> The order of a stable sort by the two keys, with 4 bytes of
   !> temporary a contact and a block instead of 36 (issue 23).
   subroutine pair_order(geo, idx, n)
      type(geometry_t), intent(in) :: geo
      integer(ip), allocatable, intent(out) :: idx(:)
      integer(ip), intent(out) :: n
      integer(ip), allocatable :: start(:)
      integer(ip) :: c, b, i, j, k
      allocate (start(geo%blocks%n + 2))
      start = 0
      n = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         n = n + 1
         b = geo%contacts%block1(c)
         start(b + 2) = start(b + 2) + 1
      end do
      allocate (idx(max(1_ip, n)))
      if (n == 0) return
      call counts_to_starts(start)     ! start(b + 1): next slot of block b
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         b = geo%contacts%block1(c)
         idx(start(b + 1)) = c
         start(b + 1) = start(b + 1) + 1
      end do
      ! start(b + 1) is now one past block b's bucket, start(b) its first slot
      do b = 1, geo%blocks%n
         do i = start(b) + 1, start(b + 1) - 1
            k = idx(i)
            j = i - 1
            do while (j >= start(b))
               if (geo%contacts%block2(idx(j)) <= geo%contacts%block2(k)) exit
               idx(j + 1) = idx(j)
               j = j - 1
            end do
            idx(j + 1) = k
         end do
      end do
   end subroutine pair_order


   !> Contacts whose feature walks (contact_geometry) have brought them onto
   !> the same features as another contact of the same blocks: keep the
   !> first, kill the others. Twins would count one touch two or three times
   !> (found: three contacts on one pair of gridpoint corners of two FDEF
   !> blocks in a direct shear, each with the full stiffness, until the run
   !> blew up). Contacts are grouped by their smaller corner id (every
   !> contact has at least one corner).
   subroutine drop_twins(geo, nbroken)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(inout) :: nbroken
      integer(ip), allocatable :: first(:), list(:), fill(:)
      integer(ip) :: c, k, i, j, a, b, n
      n = geo%corners%n
      allocate (first(n + 2), fill(n + 1))
      first = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         k = key_corner(c)
         if (k > 0) first(k + 1) = first(k + 1) + 1
      end do
      first(1) = 1
      do k = 1, n + 1
         first(k + 1) = first(k + 1) + first(k)
      end do
      allocate (list(max(1_ip, first(n + 1) - 1)))
      fill = first(1:n + 1)
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         k = key_corner(c)
         if (k <= 0) cycle
         list(fill(k)) = c
         fill(k) = fill(k) + 1
      end do
      do k = 1, n
         do i = first(k), first(k + 1) - 1
            a = list(i)
            if (.not. geo%contacts%live(a)) cycle
            do j = i + 1, first(k + 1) - 1
               b = list(j)
               if (.not. geo%contacts%live(b)) cycle
               if (same_features(a, b)) then
                  geo%contacts%live(max(a, b)) = .false.
                  nbroken = nbroken + 1
                  geo%domains_valid = .false.
               end if
            end do
         end do
      end do
   contains
      integer(ip) function key_corner(c)
         integer(ip), intent(in) :: c
         integer(ip) :: kc
         key_corner = contact_corner1(geo%contacts, c)
         kc = contact_corner2(geo%contacts, c)
         if (kc > 0 .and. (key_corner <= 0 .or. kc < key_corner)) key_corner = kc
      end function key_corner
      logical function same_features(a, b)
         integer(ip), intent(in) :: a, b
         associate (ct => geo%contacts)
            same_features = ct%block1(a) == ct%block1(b) .and. ct%block2(a) == ct%block2(b) &
                            .and. ct%kind(a) == ct%kind(b) .and. ct%end1(a) == ct%end1(b) &
                            .and. ct%end2(a) == ct%end2(b)
         end associate
      end function same_features
   end subroutine drop_twins

   !> Where contact c sits along its line: the vertex of its corner (the
   !> sharp corner that the rounding cuts off; the mean of both vertices
   !> for corner-corner), not the contact point, which lies a rounding
   !> radius inside the block's end. The lengths of the contacts of a
   !> shared stretch then add up to the stretch of the unrounded blocks,
   !> as contact_rebuild gives them; from the contact points every
   !> stretch would lose twice the rounding length (2 % of a 0.1 m
   !> joint segment at ROUND 0.001).
   subroutine corner_anchor(geo, c, x, y)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(out) :: x, y
      associate (ct => geo%contacts, co => geo%corners)
         select case (ct%kind(c))
         case (1)
            x = 0.5_wp*(co%x(ct%end1(c)) + co%x(ct%end2(c)))
            y = 0.5_wp*(co%y(ct%end1(c)) + co%y(ct%end2(c)))
         case (2)
            x = co%x(ct%end1(c))
            y = co%y(ct%end1(c))
         case (3)
            x = co%x(ct%end2(c))
            y = co%y(ct%end2(c))
         case default
            x = ct%x(c)
            y = ct%y(c)
         end select
      end associate
   end subroutine corner_anchor

end module contact_update
