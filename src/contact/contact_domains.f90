!> Domains: the voids between blocks bounded by contacts (manual Fig 3-3e;
!> UPDOM).
!>
!> Each block boundary is cut by its contacts into arcs, taken clockwise
!> around the block. With blocks clockwise, the space outside a block lies
!> to the left of its arcs, so a void is walked by following an arc to its
!> end contact, changing there to the other block of that contact and
!> following that block's next arc, until the walk closes. Each arc belongs
!> to exactly one walk; each contact ends two arcs (one per block), so it
!> gets two domains: `dom1` is reached along block1, `dom2` along block2.
!> Several contacts at one point of a block (a corner where many blocks
!> meet) are ordered by the direction into the other block, swept
!> clockwise from the incoming edge.
!>
!> Walk areas are counter-clockwise positive: a void has area >= 0 (0 for
!> tightly fitting blocks) and the region outside an assembly is walked
!> clockwise, negative: that is the outer domain. All walk areas together
!> equal minus the area of the blocks that have contacts.
module contact_domains
   use core_kinds, only: wp, ip, i1
   use core_constants, only: pi
   use model_geometry, only: geometry_t, contact_corner1, contact_corner2, contact_edge1, &
                             contact_edge2
   use model_address, only: ak_contact
   implicit none
   private
   public :: domain_rebuild, domain_release, domains_released, domains_for_sync

contains

   !> Rebuild all domains from the current contacts (ids restart at 1).
   !> Memory (issue 23): the old lists go first; the walk runs twice, once to
   !> count the domains and ring entries and once to fill lists of exactly
   !> that size; the position keys and the sweep angles that order the ends
   !> are kept for one block at a time (an arc's corners need only the
   !> position of the corner or edge an end is on: `end_pos`), the side and
   !> visit marks as bytes, and the end of a contact on its other block is
   !> looked up among that block's ends (a dozen) rather than kept for every
   !> contact: the rebuild after a dry CYCLE (domain_release) is the peak of
   !> a rigid run.
   subroutine domain_rebuild(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: nc, nb, c, b, s, e, k, n, d, cur, nxt, start_e, steps, cn, blk, cc, mx
      integer(ip), allocatable :: bstart(:), bfill(:), ent_c(:)
      integer(i1), allocatable :: ent_side(:), visited(:)
      integer(ip), allocatable :: cpos(:)
      real(wp), allocatable :: key(:), ang(:)
      integer(ip) :: nring, nd
      real(wp) :: area, lx, ly, amin
      geo%domains%n = 0
      geo%domains%nring = 0
      geo%outer_domain = 0
      geo%domains_valid = .true.
      ! released by a dry CYCLE (domain_release): the contacts' domain ids
      ! come back, one per contact slot
      if (allocated(geo%contacts%live) .and. .not. allocated(geo%contacts%dom1)) then
         allocate (geo%contacts%dom1(size(geo%contacts%live)), &
                   geo%contacts%dom2(size(geo%contacts%live)))
         geo%contacts%dom1 = 0
         geo%contacts%dom2 = 0
      end if
      nc = geo%contacts%n
      nb = geo%blocks%n
      if (nc == 0) return
      call reset_domains(geo, 0_ip)
      if (allocated(geo%domains%ring)) deallocate (geo%domains%ring)
      allocate (geo%domains%ring(0))
      ! position of each corner in its block's ring
      allocate (cpos(geo%corners%n))
      cpos = 0
      do b = 1, nb
         if (.not. geo%blocks%live(b)) cycle
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            cpos(c) = k
            c = geo%corners%next(c)
         end do
      end do
      ! block-wise lists of contact ends (CSR)
      allocate (bstart(nb + 1), bfill(nb))
      bstart = 0
      do c = 1, nc
         if (.not. geo%contacts%live(c)) cycle
         bstart(geo%contacts%block1(c) + 1) = bstart(geo%contacts%block1(c) + 1) + 1
         bstart(geo%contacts%block2(c) + 1) = bstart(geo%contacts%block2(c) + 1) + 1
      end do
      bstart(1) = 1
      do b = 1, nb
         bstart(b + 1) = bstart(b + 1) + bstart(b)
      end do
      n = bstart(nb + 1) - 1
      mx = 0
      do b = 1, nb
         mx = max(mx, bstart(b + 1) - bstart(b))
      end do
      allocate (ent_c(n), ent_side(n), key(mx), ang(mx), visited(n))
      bfill = bstart(1:nb)
      do c = 1, nc
         if (.not. geo%contacts%live(c)) cycle
         do s = 1, 2
            b = merge(geo%contacts%block1(c), geo%contacts%block2(c), s == 1)
            e = bfill(b)
            bfill(b) = e + 1
            ent_c(e) = c
            ent_side(e) = int(s, i1)
         end do
      end do
      deallocate (bfill)
      ! sort each block's ends along its boundary, ties by sweep angle
      do b = 1, nb
         do e = bstart(b), bstart(b + 1) - 1
            call position_key(geo, cpos, ent_c(e), int(ent_side(e), ip), key(e - bstart(b) + 1), &
                              ang(e - bstart(b) + 1))
         end do
         call sort_block(bstart(b), bstart(b + 1) - 1)
      end do
      deallocate (ang, key)
      ! walk the voids: count, then fill
      call walk(.false.)
      call reset_domains(geo, nd)
      deallocate (geo%domains%ring)
      allocate (geo%domains%ring(nring))
      call walk(.true.)
      geo%domains%nring = nring
      ! outer region(s): clockwise walks with a clearly negative area
      amin = 0.0_wp
      do d = 1, geo%domains%n
         geo%domains%outer(d) = geo%domains%area(d) < -1.0e-6_wp*geo%extent**2
         if (geo%domains%area(d) < amin) then
            amin = geo%domains%area(d)
            geo%outer_domain = d
         end if
      end do
   contains
      !> The position on its block of the corner, or the start of the edge,
      !> that end `ent` is on: the whole part of its position key (a key is
      !> that position plus a fraction in [1e-6, 1 - 1e-6] on an edge).
      integer(ip) function end_pos(ent)
         integer(ip), intent(in) :: ent
         end_pos = cpos(merge(geo%contacts%end1(ent_c(ent)), geo%contacts%end2(ent_c(ent)), &
                              ent_side(ent) == 1))
      end function end_pos
      !> The end of contact cn on side sd, among its block's ends.
      integer(ip) function end_of(cn, sd)
         integer(ip), intent(in) :: cn
         integer(i1), intent(in) :: sd
         integer(ip) :: bb
         bb = merge(geo%contacts%block1(cn), geo%contacts%block2(cn), sd == 1_i1)
         do end_of = bstart(bb), bstart(bb + 1) - 1
            if (ent_c(end_of) == cn .and. ent_side(end_of) == sd) return
         end do
         end_of = 0
      end function end_of
      integer(ip) function block_of(ent)
         integer(ip), intent(in) :: ent
         block_of = merge(geo%contacts%block1(ent_c(ent)), geo%contacts%block2(ent_c(ent)), &
                          ent_side(ent) == 1)
      end function block_of
      !> Insertion sort of ends lo..hi (one block's) by key(e - lo + 1),
      !> ties by the sweep angle ang(e - lo + 1).
      subroutine sort_block(lo, hi)
         integer(ip), intent(in) :: lo, hi
         integer(ip) :: p, q, tc
         integer(i1) :: ts
         real(wp) :: tk, ta
         do p = lo + 1, hi
            tc = ent_c(p); ts = ent_side(p); tk = key(p - lo + 1); ta = ang(p - lo + 1)
            q = p - 1
            do while (q >= lo)
               if (.not. after(key(q - lo + 1), ang(q - lo + 1), tk, ta)) exit
               ent_c(q + 1) = ent_c(q); ent_side(q + 1) = ent_side(q)
               key(q - lo + 2) = key(q - lo + 1); ang(q - lo + 2) = ang(q - lo + 1)
               q = q - 1
            end do
            ent_c(q + 1) = tc; ent_side(q + 1) = ts; key(q - lo + 2) = tk; ang(q - lo + 2) = ta
         end do
      end subroutine sort_block
      !> One pass over the voids: every end not yet visited starts a walk
      !> (a domain) that follows the arcs until it closes. `fill` false: count
      !> the domains (nd) and ring entries (nring); true: make them.
      subroutine walk(fill)
         logical, intent(in) :: fill
         visited = 0_i1
         nring = 0
         nd = 0
         do start_e = 1, n
            if (visited(start_e) /= 0_i1) cycle
            nd = nd + 1
            d = nd
            if (fill) then
               geo%domains%n = d
               geo%domains%first(d) = nring + 1
               geo%domains%live(d) = .true.
            end if
            area = 0.0_wp
            cur = start_e
            lx = geo%contacts%x(ent_c(cur))
            ly = geo%contacts%y(ent_c(cur))
            steps = 0
            do
               visited(cur) = 1_i1
               blk = block_of(cur)
               nxt = cur + 1
               if (nxt >= bstart(blk + 1)) nxt = bstart(blk)
               cn = ent_c(nxt)
               nring = nring + 1
               if (fill) then
                  call arc_area(blk, cur, nxt, nxt <= cur)
                  geo%domains%ring(nring) = cn
                  if (ent_side(nxt) == 1_i1) then
                     geo%contacts%dom1(cn) = d
                  else
                     geo%contacts%dom2(cn) = d
                  end if
               end if
               ! change to the other block at this contact
               cur = end_of(cn, 3_i1 - ent_side(nxt))
               steps = steps + 1
               if (cur == start_e .or. steps > n) exit
            end do
            if (fill) then
               geo%domains%count(d) = nring - geo%domains%first(d) + 1
               geo%domains%area(d) = area
            end if
         end do
      end subroutine walk
      logical function after(k1, a1, k2, a2)
         real(wp), intent(in) :: k1, a1, k2, a2
         if (abs(k1 - k2) <= 1.0e-9_wp) then
            after = a1 > a2
         else
            after = k1 > k2
         end if
      end function after
      !> Shoelace terms from the current point through the corners passed on
      !> block blk between ends e0 and e1, to the contact of e1: corner m is
      !> passed when m > key(e0) and m <= key(e1) (to 1e-9; keys are a corner
      !> position k, or k + t with t in [1e-6, 1 - 1e-6] on edge k), that is
      !> m > k0 and m <= k1 with k0, k1 the whole parts (end_pos).
      subroutine arc_area(blk, e0, e1, wrap)
         integer(ip), intent(in) :: blk, e0, e1
         logical, intent(in) :: wrap
         integer(ip) :: m, nco, q, k0, k1
         nco = geo%blocks%ncorner(blk)
         k0 = end_pos(e0)
         k1 = end_pos(e1)
         q = geo%blocks%first_corner(blk)
         if (wrap) then
            do m = 1, nco
               if (m > k0) call add_point(q)
               q = geo%corners%next(q)
            end do
            q = geo%blocks%first_corner(blk)
            do m = 1, nco
               if (m <= k1) call add_point(q)
               q = geo%corners%next(q)
            end do
         else
            do m = 1, nco
               if (m > k0 .and. m <= k1) &
                  call add_point(q)
               q = geo%corners%next(q)
            end do
         end if
         cc = ent_c(e1)
         call add_xy(geo%contacts%x(cc), geo%contacts%y(cc))
      end subroutine arc_area
      subroutine add_point(q)
         integer(ip), intent(in) :: q
         call add_xy(geo%corners%x(q), geo%corners%y(q))
      end subroutine add_point
      subroutine add_xy(x, y)
         real(wp), intent(in) :: x, y
         area = area + 0.5_wp*(lx*y - x*ly)
         lx = x
         ly = y
      end subroutine add_xy
   end subroutine domain_rebuild

   !> A CYCLE of a dry model (no FLUID: nothing in the step reads a domain)
   !> gives back the domain list, its ring and the contacts' dom1/dom2
   !> (issue 23: about 150 bytes a block at the CYCLE's peak). They are built
   !> again from the contacts and positions of the moment when something
   !> reads them (domains_released): the address synchronisation after a
   !> command when a contact was made or broken since the last one
   !> (domains_for_sync), PRINT, PLOT, SAVE and the commands that take an
   !> address (addresses_current, geometry_refresh: domains_valid is false),
   !> FLUID and the flow set-up. In UDEC 1989 the domains follow the
   !> contacts as they are made and broken during cycling (UDEC manual
   !> (ICG1.5), Section 2.2, UPDOM), so a list built from the contacts after
   !> a CYCLE is at least as faithful as the one built at its start.
   !> The 1989 address match table (geometry_t%ia) is kept: it names the
   !> domains' records at the next synchronisation.
   subroutine domain_release(geo)
      type(geometry_t), intent(inout) :: geo
      associate (dm => geo%domains)
         if (allocated(dm%live)) deallocate (dm%live, dm%outer, dm%area, dm%first, dm%count)
         if (allocated(dm%addr)) deallocate (dm%addr)
         if (allocated(dm%ring)) deallocate (dm%ring)
         dm%n = 0
         dm%nring = 0
      end associate
      geo%outer_domain = 0
      geo%domains_valid = .false.
      if (allocated(geo%contacts%dom1)) deallocate (geo%contacts%dom1, geo%contacts%dom2)
   end subroutine domain_release

   !> The domains were given back by domain_release and not built since (the
   !> contact list holds no dom1/dom2; model_geometry's grow_contacts keeps
   !> them unallocated) while there are contacts to build them from.
   logical function domains_released(geo) result(released)
      type(geometry_t), intent(in) :: geo
      released = geo%contacts%n > 0 .and. .not. allocated(geo%contacts%dom1)
   end function domains_released

   !> Before the 1989 address synchronisation (model_address): domains given
   !> back by a dry CYCLE are built again when a contact was made or broken
   !> since the last synchronisation (their keys, and so their records, may
   !> change). When every contact is the one of the last synchronisation the
   !> domains built from them would be its domains (the same rings, the
   !> same keys: each would take its own record back), so they stay released
   !> and the synchronisation leaves the domains' match table as it is
   !> (as also while a cut since has put the contacts out of date).
   subroutine domains_for_sync(geo)
      type(geometry_t), intent(inout) :: geo
      if (.not. domains_released(geo)) return
      ! contacts out of date (a cut since the CYCLE): the domains wait for
      ! the command that brings the contacts up to date (geometry_refresh)
      if (.not. geo%contacts_valid) return
      if (contacts_as_synced(geo)) return
      call domain_rebuild(geo)
   end subroutine domains_for_sync

   !> Every contact is the one of the last address synchronisation: none
   !> made (all have records) and none gone (the live ones are exactly the
   !> ones marked), and no rebuild of the contact list kept rows since.
   logical function contacts_as_synced(geo) result(same)
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c
      same = .false.
      associate (t => geo%ia%tab(ak_contact), ct => geo%contacts)
         if (geo%ia%ntab(ak_contact) /= 0 .or. t%nsynced /= ct%n) return
         if (ct%n > 0) then
            if (.not. allocated(t%synced)) return
            if (size(t%synced) < ct%n) return
         end if
         do c = 1, ct%n
            if (ct%live(c) .neqv. t%synced(c) == 1) return
            if (ct%live(c) .and. ct%addr(c) == 0) return
         end do
      end associate
      same = .true.
   end function contacts_as_synced

   !> Where contact c lies on the boundary of its block on side s: key =
   !> corner position k (+ fraction along edge k), and the clockwise sweep
   !> angle, from the reversed incoming edge, of the direction into the other
   !> block (orders contacts that share a point).
   subroutine position_key(geo, cpos, c, s, key, ang)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: cpos(:), c, s
      real(wp), intent(out) :: key, ang
      integer(ip) :: own_corner, own_edge, oth_corner, oth_edge, q
      real(wp) :: rx, ry, wx, wy, ex, ey, l, t
      if (s == 1) then
         own_corner = contact_corner1(geo%contacts, c); own_edge = contact_edge1(geo%contacts, c)
         oth_corner = contact_corner2(geo%contacts, c); oth_edge = contact_edge2(geo%contacts, c)
      else
         own_corner = contact_corner2(geo%contacts, c); own_edge = contact_edge2(geo%contacts, c)
         oth_corner = contact_corner1(geo%contacts, c); oth_edge = contact_edge1(geo%contacts, c)
      end if
      if (own_corner > 0) then
         key = real(cpos(own_corner), wp)
         q = geo%corners%prev(own_corner)
         rx = geo%corners%x(q) - geo%corners%x(own_corner)
         ry = geo%corners%y(q) - geo%corners%y(own_corner)
      else
         q = geo%corners%next(own_edge)
         ex = geo%corners%x(q) - geo%corners%x(own_edge)
         ey = geo%corners%y(q) - geo%corners%y(own_edge)
         l = hypot(ex, ey)
         t = ((geo%contacts%x(c) - geo%corners%x(own_edge))*ex + &
              (geo%contacts%y(c) - geo%corners%y(own_edge))*ey)/l**2
         t = min(1.0_wp - 1.0e-6_wp, max(1.0e-6_wp, t))
         key = real(cpos(own_edge), wp) + t
         rx = -ex
         ry = -ey
      end if
      if (oth_corner > 0) then
         call interior_bisector(geo, oth_corner, wx, wy)
      else
         ! into the other block: right of its clockwise edge
         q = geo%corners%next(oth_edge)
         ex = geo%corners%x(q) - geo%corners%x(oth_edge)
         ey = geo%corners%y(q) - geo%corners%y(oth_edge)
         wx = ey
         wy = -ex
      end if
      ang = modulo(atan2(ry, rx) - atan2(wy, wx), 2.0_wp*pi)
   end subroutine position_key

   !> Direction halving the interior angle at corner c (works for re-entrant
   !> corners too).
   subroutine interior_bisector(geo, c, wx, wy)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(out) :: wx, wy
      real(wp) :: au, av, theta, a
      integer(ip) :: p, q
      p = geo%corners%prev(c)
      q = geo%corners%next(c)
      au = atan2(geo%corners%y(p) - geo%corners%y(c), geo%corners%x(p) - geo%corners%x(c))
      av = atan2(geo%corners%y(q) - geo%corners%y(c), geo%corners%x(q) - geo%corners%x(c))
      ! interior: clockwise sweep from the next edge to the previous edge
      theta = modulo(av - au, 2.0_wp*pi)
      a = av - 0.5_wp*theta
      wx = cos(a)
      wy = sin(a)
   end subroutine interior_bisector

   subroutine reset_domains(geo, m)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: m
      associate (dm => geo%domains)
         if (allocated(dm%live)) deallocate (dm%live, dm%outer, dm%area, dm%first, dm%count)
         if (allocated(dm%addr)) deallocate (dm%addr)
         allocate (dm%live(m), dm%outer(m), dm%area(m), dm%first(m), dm%count(m), dm%addr(m))
         dm%addr = 0
         dm%live = .false.
         dm%outer = .false.
         dm%area = 0.0_wp
         dm%first = 0
         dm%count = 0
         dm%n = 0
      end associate
   end subroutine reset_domains

end module contact_domains
