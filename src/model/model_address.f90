!> 1989 addresses (UDEC manual (ICG1.5, 1989), Section 6.1, "Addresses and
!> Offsets", pp. 6-2 to 6-9): the original program kept every block, corner,
!> contact, domain, gridpoint and zone as a record in one integer/real array
!> IA, and its commands and printouts name an entity by the address of its
!> record (HISTORY SDIS(159), RSET v ia ioff, BOUNDARY CORNER ic1 ic2, PFIX
!> DOMAIN n ...). This module gives every entity of ours the address its
!> record would have had: a record of the length Section 6.1 gives (block
!> NVBL=23, corner NVCR=13, contact NVCN=32, domain NVDO=8, gridpoint NVGP=12,
!> zone NVZO=12) is taken from the junk list of freed records of that length
!> (Fig. 6-5), else at MFREE, when the entity first exists.
!>
!> Bookkeeping only: `address_sync` runs after each command (never inside the
!> cycle); nothing is stored at the addresses. Allocation order within one
!> synchronisation: new blocks, their corners, the outer domain (reserved
!> with the first block), contacts, domains, then per block its gridpoints
!> and zones. An entity that the set-up code re-creates (the corners of a
!> re-cut block, a rebuilt contact, a rebuilt domain) keeps its record if it
!> is the same item: a corner at the same place, a contact between the same
!> two blocks at the same place, a domain with the same first contact end.
!>
!> Offsets name fields (Section 6.1 tables); `address_field` maps the
!> documented offsets to our fields.
module model_address
   use core_kinds, only: wp, ip, i8, i1, l1
   use core_arrays, only: grow_double
   use core_sort, only: sort_order, lower_bound
   use model_geometry, only: geometry_t, ia_state_t, ia_table_t, joint_state_jcons3, &
                             joint_state_value
   use model_state, only: model_t
   use model_fluid, only: fluid_t
   implicit none
   private
   public :: address_sync, address_entity, address_locate, address_field
   public :: address_set_field, address_kind_name, address_describe, address_or_id
   public :: ak_block, ak_corner, ak_contact, ak_domain, ak_gridpoint, ak_zone, nak
   public :: record_length, address_split, address_ensure, address_nearest, address_keeps
   public :: address_keep_contacts, address_forget_rows, domain_centre

   integer, parameter :: ak_block = 1, ak_corner = 2, ak_contact = 3, ak_domain = 4
   integer, parameter :: ak_gridpoint = 5, ak_zone = 6, nak = 6
   !> Record lengths of Section 6.1 (NVBL, NVCR, NVCN, NVDO, NVGP, NVZO).
   integer(ip), parameter :: record_length(nak) = [23_ip, 13_ip, 32_ip, 8_ip, 12_ip, 12_ip]
   !> Queries of list_query on one entity list (query_list).
   integer, parameter :: query_starts = 1, query_nearest = 2, query_id = 3, query_holds = 4
   !> Kinds with match tables (geometry_t%ia%tab(kind)): corners, contacts and
   !> domains only (blocks, gridpoints and zones are never re-created); each
   !> table has only the columns its kind matches on (size_table). Domains
   !> keep a row per live domain; corners and contacts keep a mark per entity
   !> live at the synchronisation and read a gone one's row from its dead
   !> slot (ia_table_t, model_geometry; `gone_rows`).
   character(len=9), parameter :: kind_names(nak) = [character(len=9) :: 'block', 'corner', &
      'contact', 'domain', 'gridpoint', 'zone']
   !> Names of the words of each record this reimplementation keeps, by
   !> offset from 0 (Section 6.1 tables; '' for a word it does not keep).
   character(len=6), parameter :: block_words(0:20) = [character(len=6) :: 'type', '', '', &
      'KMAT', 'KCONS', 'KBCOD', '', 'KX', 'KY', 'KXD', 'KYD', 'KTD', 'KAREA', 'KBM', 'KBI', '', &
      'KBFX', 'KBFY', 'KBFT', 'KXL', 'KYL']
   character(len=6), parameter :: corner_words(0:9) = [character(len=6) :: '', '', '', 'KNB', '', &
      'KXP', 'KYP', 'KXCP', 'KYCP', 'KRAD']
   character(len=6), parameter :: contact_words(0:31) = [character(len=6) :: 'MCON', '', 'KB1', &
      'KB2', '', '', 'KD1', 'KD2', 'KCM', 'KCC', '', 'KXC', 'KYC', '', '', 'KCS', 'KCN', 'KCFS', &
      'KCFN', 'KCCOD', 'KCAP', 'KCQ', 'KCL', 'KGAM', 'KCNX', 'KCNY', '', '', '', '', 'KCJREV', 'KCJDS']
   character(len=6), parameter :: domain_words(0:6) = [character(len=6) :: 'MDOM', '', '', 'KDAR', &
      'KPP', '', 'KDCOD']
   character(len=6), parameter :: gridpoint_words(0:12) = [character(len=6) :: '', 'KCOR', '', &
      'KXG', 'KYG', 'KXDG', 'KYDG', 'KGFX', 'KGFY', 'KGPM', '', 'KGUX', 'KGUY']
   character(len=6), parameter :: zone_words(0:10) = [character(len=6) :: '', 'KZG', 'KZG+1', &
      'KZG+2', '', 'KZS11', 'KZS12', 'KZS22', '', '', 'KZPLAS']

contains

   pure function address_kind_name(kind) result(name)
      integer, intent(in) :: kind
      character(len=:), allocatable :: name
      name = trim(kind_names(kind))
   end function address_kind_name

   !> Give every live entity without an address its record and return the
   !> records of entities gone to the junk list.
   !> `blocks_only`: contacts and domains are out of date (a cut since the
   !> last rebuild): give blocks, corners, gridpoints and zones their records
   !> and leave contacts and domains (and their match tables) for later.
   subroutine address_sync(geo, blocks_only)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in), optional :: blocks_only
      integer(ip) :: i, b
      logical :: all, doms
      integer(i8), allocatable :: dkey(:)
      all = .true.
      if (present(blocks_only)) all = .not. blocks_only
      ! domains given back by a dry CYCLE and not built since (contact_domains'
      ! domains_for_sync built them if a contact was made or broken): the
      ! domains' match table stands as the last synchronisation left it
      doms = all .and. (allocated(geo%contacts%dom1) .or. geo%contacts%n == 0)
      call ensure_arrays(geo)
      ! 1. free what is gone, keep what is re-created
      call free_gone(geo%ia, ak_block, geo%blocks%n, geo%blocks%live, geo%blocks%addr)
      call free_gone(geo%ia, ak_gridpoint, geo%gridpoints%n, geo%gridpoints%live, geo%gridpoints%addr)
      call free_gone(geo%ia, ak_zone, geo%zones%n, geo%zones%live, geo%zones%addr)
      call match_positions(geo, ak_corner)
      if (all) then
         call match_positions(geo, ak_contact)
         if (doms) call match_domains(geo, dkey)
      end if
      ! 2. new records, in the order of the module header
      call give_new(geo%ia, ak_block, 1_ip, geo%blocks%n, geo%blocks%live, geo%blocks%addr)
      call give_new(geo%ia, ak_corner, 1_ip, geo%corners%n, geo%corners%live, geo%corners%addr)
      if (geo%ia%outer == 0 .and. geo%block_created) geo%ia%outer = take(geo%ia, record_length(ak_domain))
      if (all) then
         ! a contact given its record now can lower a domain's key: the keys
         ! of the match are then taken again for `remember`
         if (doms .and. allocated(dkey)) then
            if (any(geo%contacts%live(1:geo%contacts%n) .and. geo%contacts%addr(1:geo%contacts%n) == 0)) &
               deallocate (dkey)
         end if
         call give_new(geo%ia, ak_contact, 1_ip, geo%contacts%n, geo%contacts%live, geo%contacts%addr)
         do i = 1, merge(geo%domains%n, 0_ip, doms)
            if (.not. geo%domains%live(i)) cycle
            if (geo%domains%outer(i)) then
               if (geo%ia%outer == 0) geo%ia%outer = take(geo%ia, record_length(ak_domain))
               geo%domains%addr(i) = geo%ia%outer
            else if (geo%domains%addr(i) == 0) then
               geo%domains%addr(i) = take(geo%ia, record_length(ak_domain))
            end if
         end do
      end if
      ! (a model without zones has nothing to give per block)
      do b = 1, merge(geo%blocks%n, 0_ip, geo%gridpoints%n > 0 .or. geo%zones%n > 0)
         if (.not. geo%blocks%live(b)) cycle
         call give_new(geo%ia, ak_gridpoint, geo%blocks%gfirst(b), &
                       geo%blocks%gfirst(b) + geo%blocks%ngp(b) - 1, geo%gridpoints%live, geo%gridpoints%addr)
         call give_new(geo%ia, ak_zone, geo%blocks%zfirst(b), &
                       geo%blocks%zfirst(b) + geo%blocks%nzone(b) - 1, geo%zones%live, geo%zones%addr)
      end do
      ! 3. remember this state for the next synchronisation
      call remember(geo, all, doms, dkey)
   end subroutine address_sync

   !> Entities 1..n of one list that are gone give their records to the junk list.
   subroutine free_gone(ia, kind, n, live, addr)
      type(ia_state_t), intent(inout) :: ia
      integer, intent(in) :: kind
      integer(ip), intent(in) :: n
      logical(l1), intent(in) :: live(:)
      integer(ip), intent(inout) :: addr(:)
      integer(ip) :: i
      do i = 1, n
         if (.not. live(i) .and. addr(i) > 0) then
            call junk_push(ia, addr(i), record_length(kind))
            addr(i) = 0
         end if
      end do
   end subroutine free_gone

   !> Live entities first..last of one list without a record take one.
   subroutine give_new(ia, kind, first, last, live, addr)
      type(ia_state_t), intent(inout) :: ia
      integer, intent(in) :: kind
      integer(ip), intent(in) :: first, last
      logical(l1), intent(in) :: live(:)
      integer(ip), intent(inout) :: addr(:)
      integer(ip) :: i
      do i = first, last
         if (live(i) .and. addr(i) == 0) addr(i) = take(ia, record_length(kind))
      end do
   end subroutine give_new

   !> A cut split block `b`, giving new block `newb`: the 1989 program inserted
   !> a corner into `b`'s ring where the cut crosses each edge (at P1, the
   !> cut's start, then at P2) and split the ring there, copying the two
   !> inserted corners for the other piece (P2 first). The inserted corner
   !> stays with the piece that holds the start of the crossed edge (its
   !> clockwise predecessor); the copy goes with the other piece. Records in
   !> that order, after the new block's: the Appendix B, Problem E deck's
   !> corners 107 (P1, bottom), 120 (P2, top), 133 (P2, bottom), 146 (P1, top).
   !> `new1`/`new2`: the cut made a corner at P1 / P2 (not through a vertex);
   !> (s1x, s1y), (s2x, s2y): start of the crossed edge.
   subroutine address_split(geo, b, newb, p1x, p1y, new1, s1x, s1y, p2x, p2y, new2, s2x, s2y)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: b, newb
      real(wp), intent(in) :: p1x, p1y, s1x, s1y, p2x, p2y, s2x, s2y
      logical, intent(in) :: new1, new2
      integer(ip) :: o1, c1, o2, c2
      ! blocks%addr and corners%addr grow with their lists (grow_blocks, grow_corners)
      if (geo%blocks%addr(b) == 0) geo%blocks%addr(b) = take(geo%ia, record_length(ak_block))
      if (geo%blocks%addr(newb) == 0) geo%blocks%addr(newb) = take(geo%ia, record_length(ak_block))
      o1 = 0; c1 = 0; o2 = 0; c2 = 0
      if (new1) call pair(p1x, p1y, s1x, s1y, o1, c1)
      if (new2) call pair(p2x, p2y, s2x, s2y, o2, c2)
      call give(o1)
      call give(o2)
      call give(c2)
      call give(c1)
   contains
      subroutine give(c)
         integer(ip), intent(in) :: c
         if (c == 0) return
         if (geo%corners%addr(c) == 0) geo%corners%addr(c) = take(geo%ia, record_length(ak_corner))
      end subroutine give
      !> The corners of b and newb at (px, py): the one whose predecessor is
      !> at (sx, sy) is the inserted one.
      subroutine pair(px, py, sx, sy, orig, copy)
         real(wp), intent(in) :: px, py, sx, sy
         integer(ip), intent(out) :: orig, copy
         integer(ip) :: cb, cn, q
         real(wp) :: h
         h = 1.0e-6_wp*max(geo%extent, 1.0_wp) + 10.0_wp*geo%tol
         cb = corner_at(b, px, py, h)
         cn = corner_at(newb, px, py, h)
         orig = 0
         copy = 0
         if (cb == 0 .or. cn == 0) return
         q = geo%corners%prev(cb)
         if (hypot(geo%corners%x(q) - sx, geo%corners%y(q) - sy) <= h) then
            orig = cb
            copy = cn
         else
            orig = cn
            copy = cb
         end if
      end subroutine pair
      integer(ip) function corner_at(blk, px, py, h) result(found)
         integer(ip), intent(in) :: blk
         real(wp), intent(in) :: px, py, h
         integer(ip) :: k, c
         found = 0
         c = geo%blocks%first_corner(blk)
         do k = 1, geo%blocks%ncorner(blk)
            if (hypot(geo%corners%x(c) - px, geo%corners%y(c) - py) <= h) then
               found = c
               return
            end if
            c = geo%corners%next(c)
         end do
      end function corner_at
   end subroutine address_split

   !> The address arrays exist and are as long as their lists (before SAVE).
   subroutine address_ensure(geo)
      type(geometry_t), intent(inout) :: geo
      call ensure_arrays(geo)
   end subroutine address_ensure

   !> Arrays of a model read from an older save file, or never grown.
   subroutine ensure_arrays(geo)
      type(geometry_t), intent(inout) :: geo
      if (allocated(geo%blocks%live)) call fit(geo%blocks%addr, size(geo%blocks%live))
      if (allocated(geo%corners%live)) call fit(geo%corners%addr, size(geo%corners%live))
      if (allocated(geo%contacts%live)) call fit(geo%contacts%addr, size(geo%contacts%live))
      if (allocated(geo%domains%live)) call fit(geo%domains%addr, size(geo%domains%live))
      if (allocated(geo%gridpoints%live)) call fit(geo%gridpoints%addr, size(geo%gridpoints%live))
      if (allocated(geo%zones%live)) call fit(geo%zones%addr, size(geo%zones%live))
      if (.not. allocated(geo%ia%tab(ak_corner)%addr)) then
         call size_table(geo%ia%tab(ak_corner), ak_corner, 0_ip)
         call size_table(geo%ia%tab(ak_contact), ak_contact, 0_ip)
         call size_table(geo%ia%tab(ak_domain), ak_domain, 0_ip)
         geo%ia%ntab = 0
      end if
      if (.not. allocated(geo%ia%junk_addr) .or. .not. allocated(geo%ia%junk_len)) then
         if (allocated(geo%ia%junk_addr)) deallocate (geo%ia%junk_addr)
         if (allocated(geo%ia%junk_len)) deallocate (geo%ia%junk_len)
         allocate (geo%ia%junk_addr(16), geo%ia%junk_len(16))
         geo%ia%njunk = 0
      end if
   contains
      subroutine fit(a, n)
         integer(ip), allocatable, intent(inout) :: a(:)
         integer, intent(in) :: n
         integer(ip), allocatable :: t(:)
         integer :: m
         if (allocated(a)) then
            if (size(a) >= n) return
            allocate (t(n))
            t = 0
            m = size(a)
            t(1:m) = a
            call move_alloc(t, a)
         else
            allocate (a(max(n, 0)))
            a = 0
         end if
      end subroutine fit
   end subroutine ensure_arrays

   !> A record of length `len`: the latest freed one of that length, else MFREE.
   integer(ip) function take(ia, len) result(a)
      type(ia_state_t), intent(inout) :: ia
      integer(ip), intent(in) :: len
      integer(ip) :: j
      do j = ia%njunk, 1, -1
         if (ia%junk_len(j) == len) then
            a = ia%junk_addr(j)
            ia%junk_addr(j:ia%njunk - 1) = ia%junk_addr(j + 1:ia%njunk)
            ia%junk_len(j:ia%njunk - 1) = ia%junk_len(j + 1:ia%njunk)
            ia%njunk = ia%njunk - 1
            return
         end if
      end do
      a = ia%mfree
      ia%mfree = ia%mfree + len
   end function take

   subroutine junk_push(ia, a, len)
      type(ia_state_t), intent(inout) :: ia
      integer(ip), intent(in) :: a, len
      if (.not. allocated(ia%junk_addr)) allocate (ia%junk_addr(16), ia%junk_len(16))
      if (ia%njunk >= size(ia%junk_addr)) call grow_double(ia%junk_addr)
      if (ia%njunk >= size(ia%junk_len)) call grow_double(ia%junk_len)
      ia%njunk = ia%njunk + 1
      ia%junk_addr(ia%njunk) = a
      ia%junk_len(ia%njunk) = len
   end subroutine junk_push

   !> Corners and contacts: a live entity without address takes the record of
   !> an entity of the last synchronisation that is gone, at the same place
   !> (corners: same block preferred; contacts: the same two blocks). Records
   !> of gone entities not taken over return to the junk list.
   subroutine match_positions(geo, kind)
      type(geometry_t), intent(inout) :: geo
      integer, intent(in) :: kind
      integer(ip) :: nt, n, i, j, lo, mid, best, dcx
      integer(ip), allocatable :: perm(:), p2(:), tperm(:), addr(:)
      real(wp), allocatable :: kx(:), ky(:), taddr(:)
      logical, allocatable :: avail(:)
      real(wp) :: h, x, y, d, dbest, cs, qx, qy
      integer(ip) :: b1, b2
      logical :: pref, bpref
      logical(l1), allocatable :: live(:)
      type(ia_table_t) :: tab
      ! the entities of the last synchronisation that are gone
      call gone_rows(geo, kind, tab, nt)
      ! none (a command that made and killed no corner or contact): nothing
      ! to match or free (Issue 23: no pass over the live ones)
      if (nt == 0) then
         call forget_table(geo, kind)
         return
      end if
      ! the list's state before matching (each entity's own entry is read
      ! before set_addr changes it)
      n = merge(geo%corners%n, geo%contacts%n, kind == ak_corner)
      allocate (live(n), addr(n))
      if (n > 0 .and. kind == ak_corner) then
         live = geo%corners%live(1:n)
         addr = geo%corners%addr(1:n)
      else if (n > 0) then
         live = geo%contacts%live(1:n)
         addr = geo%contacts%addr(1:n)
      end if
      ! records still owned by a live entity are not free: each live
      ! entity's record is looked up among the nt rows' (sorted once; the
      ! rows are few against the live entities, Issue 23)
      allocate (avail(nt), tperm(nt))
      avail = .true.
      call sort_order(tab%addr(1:nt), tperm)
      taddr = real(tab%addr(tperm), wp)
      do i = 1, n
         if (.not. live(i) .or. addr(i) <= 0) cycle
         lo = lower_bound(taddr, real(addr(i), wp))
         do mid = lo, nt
            if (taddr(mid) /= real(addr(i), wp)) exit
            avail(tperm(mid)) = .false.
         end do
      end do
      ! table entries sorted by cell (cx, cy) of size 2h: a match lies in
      ! one of the 3 x 3 cells around the query's (many corners share one x
      ! along a joint, so a sort by x alone would scan them all)
      h = 1.0e-6_wp*max(geo%extent, 1.0_wp) + 10.0_wp*geo%tol
      cs = 2.0_wp*h
      if (nt > 0) then
         allocate (perm(nt), p2(nt), kx(nt), ky(nt))
         kx = real(floor(tab%x(1:nt)/cs, i8), wp)
         ky = real(floor(tab%y(1:nt)/cs, i8), wp)
         call sort_order(ky, p2)
         call sort_order(kx(p2), perm)
         perm = p2(perm)
         kx = kx(perm)
         ky = ky(perm)
      end if
      do i = 1, n
         if (nt == 0) exit
         if (.not. live(i) .or. addr(i) > 0) cycle
         call entity_key(i, x, y, b1, b2)
         qx = real(floor(x/cs, i8), wp)
         qy = real(floor(y/cs, i8), wp)
         best = 0
         dbest = huge(1.0_wp)
         bpref = .false.
         do dcx = -1, 1
            lo = first_not_below(kx, ky, qx + dcx, qy - 1)
            do mid = lo, nt
               if (kx(mid) /= qx + dcx .or. ky(mid) > qy + 1) exit
               j = perm(mid)
               if (.not. avail(j)) cycle
               if (abs(tab%x(j) - x) > h .or. abs(tab%y(j) - y) > h) cycle
               if (kind == ak_contact) then
                  if (.not. ((tab%b1(j) == b1 .and. tab%b2(j) == b2) .or. &
                             (tab%b1(j) == b2 .and. tab%b2(j) == b1))) cycle
                  pref = .true.
               else
                  pref = tab%b1(j) == b1
               end if
               d = hypot(tab%x(j) - x, tab%y(j) - y)
               if ((pref .and. .not. bpref) .or. ((pref .eqv. bpref) .and. d < dbest)) then
                  best = j
                  dbest = d
                  bpref = pref
               end if
            end do
         end do
         if (best > 0) then
            avail(best) = .false.
            call set_addr(i, tab%addr(best))
         end if
      end do
      do j = 1, nt
         if (avail(j)) call junk_push(geo%ia, tab%addr(j), record_length(kind))
      end do
      call forget_table(geo, kind)
   contains
      subroutine entity_key(i_, x_, y_, b1_, b2_)
         integer(ip), intent(in) :: i_
         real(wp), intent(out) :: x_, y_
         integer(ip), intent(out) :: b1_, b2_
         if (kind == ak_corner) then
            x_ = geo%corners%x(i_)
            y_ = geo%corners%y(i_)
            b1_ = geo%corners%block(i_)
            b2_ = 0
         else
            x_ = geo%contacts%x(i_)
            y_ = geo%contacts%y(i_)
            b1_ = geo%contacts%block1(i_)
            b2_ = geo%contacts%block2(i_)
         end if
      end subroutine entity_key
      subroutine set_addr(i_, a_)
         integer(ip), intent(in) :: i_, a_
         if (kind == ak_corner) then
            geo%corners%addr(i_) = a_
         else
            geo%contacts%addr(i_) = a_
         end if
      end subroutine set_addr
   end subroutine match_positions

   !> The first entry of the pairs (k1, k2), sorted ascending by k1 then k2,
   !> that is not below (q1, q2); size + 1 if there is none (binary search).
   pure integer(ip) function first_not_below(k1, k2, q1, q2) result(lo)
      real(wp), intent(in) :: k1(:), k2(:), q1, q2
      integer(ip) :: hi, mid
      lo = 1
      hi = size(k1, kind=ip) + 1
      do while (lo < hi)
         mid = (lo + hi)/2
         if (k1(mid) < q1 .or. (k1(mid) == q1 .and. k2(mid) < q2)) then
            lo = mid + 1
         else
            hi = mid
         end if
      end do
   end function first_not_below

   !> The match rows of `kind` are matched or freed: the rows kept by a
   !> rebuild go.
   subroutine forget_table(geo, kind)
      type(geometry_t), intent(inout) :: geo
      integer, intent(in) :: kind
      geo%ia%ntab(kind) = 0
      call size_table(geo%ia%tab(kind), kind, 0_ip, fresh=.true.)
   end subroutine forget_table

   !> Domains are rebuilt whole; a domain keeps the record of the domain of the
   !> last synchronisation with the same key: its first contact end, the
   !> smallest (contact address, side) on its ring.
   !> `key`: each domain's key (domain_keys), for `remember` (the contact
   !> records it is made of do not change between the two).
   subroutine match_domains(geo, key)
      type(geometry_t), intent(inout) :: geo
      integer(i8), allocatable, intent(out) :: key(:)
      integer(ip) :: nt, j, d, lo, mid
      integer(ip), allocatable :: perm(:)
      logical, allocatable :: avail(:)
      real(wp), allocatable :: sorted_key(:), zero(:)
      nt = geo%ia%ntab(ak_domain)
      call domain_keys(geo, key)
      ! the table is the live domains' own rows, in order (no domain rebuilt
      ! and no contact record changed since the last synchronisation): each
      ! would find its own record again and none would be freed (Issue 23:
      ! no sort)
      if (domains_as_remembered(geo, key, nt)) then
         ! a list rebuilt from the same contacts (records 0: a dry CYCLE's
         ! domains built on demand, contact_domains) takes its rows back in
         ! order, as the match below would give them (no sort, issue 23)
         j = 0
         do d = 1, geo%domains%n
            if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) cycle
            j = j + 1
            geo%domains%addr(d) = geo%ia%tab(ak_domain)%addr(j)
         end do
         return
      end if
      allocate (avail(nt), perm(nt), zero(nt))
      avail = .true.
      zero = 0.0_wp
      ! table keys in ascending order (keys, 2 x a contact address + 0 or 1,
      ! are exact in real(wp): below 2**53)
      allocate (sorted_key(nt))
      if (nt > 0) then
         call sort_order(real(geo%ia%tab(ak_domain)%key(1:nt), wp), perm)
         sorted_key = real(geo%ia%tab(ak_domain)%key(perm), wp)
      end if
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) cycle
         if (key(d) == huge(1_i8) .or. nt == 0) cycle
         lo = first_not_below(zero, sorted_key, 0.0_wp, real(key(d), wp))
         do mid = lo, nt
            j = perm(mid)
            if (geo%ia%tab(ak_domain)%key(j) /= key(d)) exit
            if (avail(j)) then
               geo%domains%addr(d) = geo%ia%tab(ak_domain)%addr(j)
               avail(j) = .false.
               exit
            end if
         end do
      end do
      do j = 1, nt
         if (avail(j)) call junk_push(geo%ia, geo%ia%tab(ak_domain)%addr(j), record_length(ak_domain))
      end do
   end subroutine match_domains

   !> The domain table holds, row after row, each live inner domain's record
   !> (or the domain has none yet: rebuilt since) and its key `key` as
   !> `remember` wrote them, and every key is a real one (keys are contact
   !> ends, so no two domains share one).
   logical function domains_as_remembered(geo, key, nt) result(same)
      type(geometry_t), intent(in) :: geo
      integer(i8), intent(in) :: key(:)
      integer(ip), intent(in) :: nt
      integer(ip) :: d, n
      same = .false.
      n = 0
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) cycle
         n = n + 1
         if (n > nt) return
         if (key(d) == huge(1_i8) .or. geo%ia%tab(ak_domain)%key(n) /= key(d)) return
         if (geo%domains%addr(d) /= 0 .and. geo%ia%tab(ak_domain)%addr(n) /= geo%domains%addr(d)) return
      end do
      same = n == nt
   end function domains_as_remembered

   !> Key of each domain: min over its ring of 2*(contact address) + side - 1
   !> (contact addresses of this synchronisation's matching; a new contact
   !> without an address yet does not count).
   subroutine domain_keys(geo, key)
      type(geometry_t), intent(in) :: geo
      integer(i8), allocatable, intent(out) :: key(:)
      integer(ip) :: c, d
      integer(i8) :: k
      allocate (key(max(geo%domains%n, 0_ip)))
      key = huge(1_i8)
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c) .or. geo%contacts%addr(c) == 0) cycle
         k = 2_i8*int(geo%contacts%addr(c), i8)
         d = geo%contacts%dom1(c)
         if (d > 0 .and. d <= geo%domains%n) key(d) = min(key(d), k)
         d = geo%contacts%dom2(c)
         if (d > 0 .and. d <= geo%domains%n) key(d) = min(key(d), k + 1_i8)
      end do
   end subroutine domain_keys

   !> `doms`: the domains are built (not released by a dry CYCLE); `key`
   !> their keys as match_domains computed them, unallocated when a contact
   !> took a record since (issue 23: domain_keys once a synchronisation
   !> when no contact is new).
   subroutine remember(geo, all, doms, key)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in) :: all, doms
      integer(i8), allocatable, intent(inout) :: key(:)
      integer(ip) :: i, n
      call mark_synced(geo%ia%tab(ak_corner), geo%corners%n, geo%corners%live)
      if (.not. all) return
      call mark_synced(geo%ia%tab(ak_contact), geo%contacts%n, geo%contacts%live)
      if (.not. doms) return
      n = 0
      if (allocated(geo%domains%live)) n = int(count(geo%domains%live(1:geo%domains%n)), ip)
      call size_table(geo%ia%tab(ak_domain), ak_domain, n)
      if (.not. allocated(key)) call domain_keys(geo, key)
      n = 0
      do i = 1, geo%domains%n
         if (.not. geo%domains%live(i) .or. geo%domains%outer(i)) cycle
         n = n + 1
         geo%ia%tab(ak_domain)%addr(n) = geo%domains%addr(i)
         geo%ia%tab(ak_domain)%key(n) = key(i)
      end do
      geo%ia%ntab(ak_domain) = n
   end subroutine remember

   !> Entities 1..n of a corner or contact list live now are marked as
   !> the last synchronisation's (one byte each; ia_table_t).
   subroutine mark_synced(t, n, live)
      type(ia_table_t), intent(inout) :: t
      integer(ip), intent(in) :: n
      logical(l1), allocatable, intent(in) :: live(:)
      t%nsynced = 0
      if (n <= 0 .or. .not. allocated(live)) return
      if (allocated(t%synced)) then
         if (size(t%synced, kind=ip) < n) deallocate (t%synced)
      end if
      if (.not. allocated(t%synced)) allocate (t%synced(n + n/64_ip + 64_ip))
      t%synced(1:n) = merge(1_i1, 0_i1, live(1:n))
      t%nsynced = n
   end subroutine mark_synced

   !> The match rows of corners or contacts (`kind`) for a synchronisation:
   !> the rows a contact rebuild kept (address_keep_contacts), then every
   !> entity marked at the last synchronisation that is gone since, read
   !> from its dead slot, in id order (as the rows of all the live entities
   !> were once kept; the live ones, which keep their records, matched
   !> nothing). `nt` rows.
   subroutine gone_rows(geo, kind, t, nt)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      type(ia_table_t), intent(out) :: t
      integer(ip), intent(out) :: nt
      integer(ip) :: nk
      nk = geo%ia%ntab(kind)
      associate (k => geo%ia%tab(kind))
         if (kind == ak_corner) then
            call size_table(t, kind, nk + synced_rows(k, geo%corners%n, geo%corners%live, .true.))
         else
            call size_table(t, kind, nk + synced_rows(k, geo%contacts%n, geo%contacts%live, .true.))
         end if
         call copy_rows(t, k, kind, nk)
         nt = nk
         if (kind == ak_corner) then
            call add_synced_rows(t, nt, k%synced, k%nsynced, geo%corners%n, geo%corners%live, geo%corners%addr, &
                                 geo%corners%x, geo%corners%y, geo%corners%block, gone_only=.true.)
         else
            call add_synced_rows(t, nt, k%synced, k%nsynced, geo%contacts%n, geo%contacts%live, &
                                 geo%contacts%addr, geo%contacts%x, geo%contacts%y, geo%contacts%block1, &
                                 geo%contacts%block2, gone_only=.true.)
         end if
      end associate
   end subroutine gone_rows

   !> Before contact_rebuild overwrites the contact list: the contacts of the
   !> last synchronisation, gone or not, keep their rows (address, blocks,
   !> position) in the contact match table, so that the next synchronisation
   !> can give a contact of the new list the record of the one at its place;
   !> their marks go (their slots are about to be reused).
   subroutine address_keep_contacts(geo)
      type(geometry_t), intent(inout) :: geo
      type(ia_table_t) :: rows
      integer(ip) :: nk, nt, m
      associate (k => geo%ia%tab(ak_contact))
         m = synced_rows(k, geo%contacts%n, geo%contacts%live, .false.)
         if (m > 0) then
            ! the rows of an earlier rebuild stay first (a rebuild unmarks
            ! what it keeps, so a second one before the synchronisation
            ! adds none)
            nk = geo%ia%ntab(ak_contact)
            call size_table(rows, ak_contact, nk + m)
            call copy_rows(rows, k, ak_contact, nk)
            nt = nk
            call add_synced_rows(rows, nt, k%synced, k%nsynced, geo%contacts%n, geo%contacts%live, &
                                 geo%contacts%addr, geo%contacts%x, geo%contacts%y, geo%contacts%block1, &
                                 geo%contacts%block2, gone_only=.false.)
            call move_alloc(rows%addr, k%addr)
            call move_alloc(rows%b1, k%b1)
            call move_alloc(rows%b2, k%b2)
            call move_alloc(rows%x, k%x)
            call move_alloc(rows%y, k%y)
            geo%ia%ntab(ak_contact) = nt
         end if
         k%nsynced = 0
      end associate
   end subroutine address_keep_contacts

   !> A model read from a save file starts without match rows or marks (they
   !> are not saved).
   subroutine address_forget_rows(geo)
      type(geometry_t), intent(inout) :: geo
      geo%ia%ntab = 0
      geo%ia%tab(:)%nsynced = 0
   end subroutine address_forget_rows

   !> Number of entities marked in `k` (of a list of n, `live`): all of them,
   !> or (gone_only) those not live now.
   integer(ip) function synced_rows(k, n, live, gone_only) result(m)
      type(ia_table_t), intent(in) :: k
      integer(ip), intent(in) :: n
      logical(l1), allocatable, intent(in) :: live(:)
      logical, intent(in) :: gone_only
      integer(ip) :: i
      m = 0
      do i = 1, min(k%nsynced, n)
         if (k%synced(i) /= 1_i1) cycle
         if (gone_only .and. live(i)) cycle
         m = m + 1
      end do
   end function synced_rows

   !> Rows 1..nk of table k (corners or contacts) into t (sized for them).
   subroutine copy_rows(t, k, kind, nk)
      type(ia_table_t), intent(inout) :: t
      type(ia_table_t), intent(in) :: k
      integer, intent(in) :: kind
      integer(ip), intent(in) :: nk
      if (nk <= 0) return
      t%addr(1:nk) = k%addr(1:nk)
      t%b1(1:nk) = k%b1(1:nk)
      t%x(1:nk) = k%x(1:nk)
      t%y(1:nk) = k%y(1:nk)
      if (kind == ak_contact) t%b2(1:nk) = k%b2(1:nk)
   end subroutine copy_rows

   !> Append to the rows of t (nt of them) the entities marked in `synced`
   !> (1..nsynced, of a list of n): all of them, or (gone_only) those not
   !> live now; address, block(s) (b2: the second block of a contact) and
   !> position.
   subroutine add_synced_rows(t, nt, synced, nsynced, n, live, addr, x, y, b1, b2, gone_only)
      type(ia_table_t), intent(inout) :: t
      integer(ip), intent(inout) :: nt
      integer(i1), allocatable, intent(in) :: synced(:)
      integer(ip), intent(in) :: nsynced, n
      logical(l1), allocatable, intent(in) :: live(:)
      integer(ip), intent(in) :: addr(:), b1(:)
      real(wp), intent(in) :: x(:), y(:)
      integer(ip), intent(in), optional :: b2(:)
      logical, intent(in) :: gone_only
      integer(ip) :: i
      do i = 1, min(nsynced, n)
         if (synced(i) /= 1_i1) cycle
         if (gone_only .and. live(i)) cycle
         nt = nt + 1
         t%addr(nt) = addr(i)
         t%b1(nt) = b1(i)
         if (present(b2)) t%b2(nt) = b2(i)
         t%x(nt) = x(i)
         t%y(nt) = y(i)
      end do
   end subroutine add_synced_rows

   !> Number of live entities of a list of n slots.
   pure integer(ip) function live_count(live, n) result(k)
      logical(l1), allocatable, intent(in) :: live(:)
      integer(ip), intent(in) :: n
      k = 0
      if (.not. allocated(live) .or. n <= 0) return
      k = int(count(live(1:n)), ip)
   end function live_count

   !> The match table of `kind` with room for at least m rows (its contents
   !> are rewritten whole by `remember`, so nothing is kept when it grows;
   !> `fresh`: exactly m, also when it is larger now):
   !> address and block columns, the second block for contacts, positions
   !> for corners and contacts, the key for domains.
   subroutine size_table(t, kind, m, fresh)
      type(ia_table_t), intent(inout) :: t
      integer, intent(in) :: kind
      integer(ip), intent(in) :: m
      logical, intent(in), optional :: fresh
      logical :: keep
      keep = .true.
      if (present(fresh)) keep = .not. fresh
      if (allocated(t%addr)) then
         if (keep .and. size(t%addr, kind=ip) >= m) return
         deallocate (t%addr)
         if (allocated(t%b1)) deallocate (t%b1)
         if (allocated(t%b2)) deallocate (t%b2)
         if (allocated(t%x)) deallocate (t%x)
         if (allocated(t%y)) deallocate (t%y)
         if (allocated(t%key)) deallocate (t%key)
      end if
      allocate (t%addr(m), source=0_ip)
      if (kind == ak_domain) then
         allocate (t%key(m), source=0_i8)
      else
         allocate (t%b1(m), source=0_ip)
         allocate (t%x(m), t%y(m), source=0.0_wp)
         if (kind == ak_contact) allocate (t%b2(m), source=0_ip)
      end if
   end subroutine size_table

   !> The live entity of `kind` whose record starts at address `a` (0: none).
   integer(ip) function address_entity(geo, kind, a) result(id)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      integer(ip), intent(in) :: a
      id = 0
      if (a <= 0) return
      id = list_query(geo, kind, query_starts, a)
   end function address_entity

   !> The live entity of `kind` whose record starts nearest to address `a`
   !> (the lower one of two equally near; 0: no entity of that kind has a
   !> record). For a history naming a 1989 address this program does not
   !> reproduce (commands_address): records are taken in the order the set-up
   !> creates the entities, so the nearest record is one made at about the
   !> same stage of the set-up; not the same item in general.
   integer(ip) function address_nearest(geo, kind, a) result(id)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      integer(ip), intent(in) :: a
      id = list_query(geo, kind, query_nearest, a)
   end function address_nearest

   !> `query` (query_starts, ..) on the list of entities of `kind`; 0 for
   !> an unknown kind. `start`: the address of the record found by
   !> query_starts or query_holds.
   integer(ip) function list_query(geo, kind, query, a, start) result(id)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind, query
      integer(ip), intent(in) :: a
      integer(ip), intent(out), optional :: start
      integer(ip) :: at
      at = 0
      select case (kind)
      case (ak_block)
         id = query_list(query, kind, geo%blocks%n, geo%blocks%live, geo%blocks%addr, a, at)
      case (ak_corner)
         id = query_list(query, kind, geo%corners%n, geo%corners%live, geo%corners%addr, a, at)
      case (ak_contact)
         id = query_list(query, kind, geo%contacts%n, geo%contacts%live, geo%contacts%addr, a, at)
      case (ak_domain)
         id = query_list(query, kind, geo%domains%n, geo%domains%live, geo%domains%addr, a, at)
      case (ak_gridpoint)
         id = query_list(query, kind, geo%gridpoints%n, geo%gridpoints%live, geo%gridpoints%addr, a, at)
      case (ak_zone)
         id = query_list(query, kind, geo%zones%n, geo%zones%live, geo%zones%addr, a, at)
      case default
         id = 0
      end select
      if (present(start)) start = at
   end function list_query

   !> The entity of the list 1..n (`live`, record addresses `addr`) that
   !> `query` asks for with the number `a`, 0 if none:
   !> query_starts: the last live one whose record starts at address a;
   !> query_nearest: the live one whose record starts nearest to a (the
   !>   lower address of two equally near; arrays not allocated: none);
   !> query_id: a itself if it is a live entity (an id, not an address);
   !> query_holds: the first live one whose record (`kind`) holds address a.
   !> `at`: the start of the record found by query_starts or query_holds.
   integer(ip) function query_list(query, kind, n, live, addr, a, at) result(found)
      integer, intent(in) :: query, kind
      integer(ip), intent(in) :: n, a
      logical(l1), allocatable, intent(in) :: live(:)
      integer(ip), allocatable, intent(in) :: addr(:)
      integer(ip), intent(inout) :: at
      integer(ip) :: i, d, best
      found = 0
      select case (query)
      case (query_starts)
         do i = n, 1, -1
            if (live(i) .and. addr(i) == a) then
               found = i
               at = a
               return
            end if
         end do
      case (query_nearest)
         if (.not. allocated(live) .or. .not. allocated(addr)) return
         best = huge(1_ip)
         do i = 1, min(n, int(size(addr), ip), int(size(live), ip))
            if (.not. live(i) .or. addr(i) <= 0) cycle
            d = abs(addr(i) - a)
            if (d < best .or. (d == best .and. addr(i) < addr(max(found, 1_ip)))) then
               best = d
               found = i
            end if
         end do
      case (query_id)
         if (a > n) return
         if (live(a)) found = a
      case (query_holds)
         do i = 1, n
            if (.not. live(i) .or. addr(i) <= 0) cycle
            if (a >= addr(i) .and. a < addr(i) + record_length(kind)) then
               found = i
               at = addr(i)
               return
            end if
         end do
      end select
   end function query_list

   !> Whether offset `off` of a record of `kind` is a word this program keeps
   !> (the Section 6.1 tables above).
   pure logical function address_keeps(kind, off) result(keeps)
      integer, intent(in) :: kind
      integer(ip), intent(in) :: off
      keeps = .false.
      if (off < 0) return
      select case (kind)
      case (ak_block); if (off <= ubound(block_words, 1)) keeps = block_words(off) /= ''
      case (ak_corner); if (off <= ubound(corner_words, 1)) keeps = corner_words(off) /= ''
      case (ak_contact); if (off <= ubound(contact_words, 1)) keeps = contact_words(off) /= ''
      case (ak_domain); if (off <= ubound(domain_words, 1)) keeps = domain_words(off) /= ''
      case (ak_gridpoint)
         if (off <= ubound(gridpoint_words, 1)) keeps = gridpoint_words(off) /= ''
      case (ak_zone); if (off <= ubound(zone_words, 1)) keeps = zone_words(off) /= ''
      end select
   end function address_keeps

   !> Entity of `kind` named by `n` in a command: the one at address n, else
   !> (older decks of ours) the one with id n when no entity has address n.
   !> `how` tells which: 'address', 'id' or '' (none).
   subroutine address_or_id(geo, kind, n, id, how)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      integer(ip), intent(in) :: n
      integer(ip), intent(out) :: id
      character(len=:), allocatable, intent(out) :: how
      id = address_entity(geo, kind, n)
      how = 'address'
      if (id > 0) return
      how = ''
      if (n < 1) return
      ! ids stand for blocks, corners, contacts and domains only
      if (kind <= ak_domain) id = list_query(geo, kind, query_id, n)
      if (id > 0) how = 'id'
   end subroutine address_or_id

   !> The live entity whose record holds location `a` (kind 0: none) and the
   !> offset of `a` in it.
   subroutine address_locate(geo, a, kind, id, off)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: a
      integer, intent(out) :: kind
      integer(ip), intent(out) :: id, off
      integer, parameter :: order(2) = [query_starts, query_holds]
      integer :: j, k
      integer(ip) :: i, start
      kind = 0
      id = 0
      off = 0
      if (a <= 0) return
      ! a record starting at a first, then one holding it
      do j = 1, 2
         do k = 1, nak
            i = list_query(geo, k, order(j), a, start)
            if (i > 0) then
               kind = k
               id = i
               off = a - start
               return
            end if
         end do
      end do
   end subroutine address_locate

   !> One line naming entity `id` of `kind`: address, our id, position.
   function address_describe(model, kind, id) result(text)
      type(model_t), intent(in) :: model
      integer, intent(in) :: kind
      integer(ip), intent(in) :: id
      character(len=:), allocatable :: text
      character(len=200) :: buf
      real(wp) :: x, y
      integer(ip) :: a
      associate (geo => model%geometry)
         select case (kind)
         case (ak_block)
            a = geo%blocks%addr(id); x = geo%blocks%xc(id); y = geo%blocks%yc(id)
         case (ak_corner)
            a = geo%corners%addr(id); x = geo%corners%x(id); y = geo%corners%y(id)
         case (ak_contact)
            a = geo%contacts%addr(id); x = geo%contacts%x(id); y = geo%contacts%y(id)
         case (ak_domain)
            a = geo%domains%addr(id); call domain_centre(geo, id, x, y)
         case (ak_gridpoint)
            a = geo%gridpoints%addr(id); x = geo%gridpoints%x(id); y = geo%gridpoints%y(id)
         case default
            a = geo%zones%addr(id)
            x = (geo%gridpoints%x(geo%zones%g1(id)) + geo%gridpoints%x(geo%zones%g2(id)) + &
                 geo%gridpoints%x(geo%zones%g3(id)))/3.0_wp
            y = (geo%gridpoints%y(geo%zones%g1(id)) + geo%gridpoints%y(geo%zones%g2(id)) + &
                 geo%gridpoints%y(geo%zones%g3(id)))/3.0_wp
         end select
      end associate
      write (buf, '(a,1x,a,i0,a,i0,a,g0.6,a,g0.6,a)') kind_names(kind)(1:len_trim(kind_names(kind))), &
         '(address ', a, ', id ', id, ') at (', x, ',', y, ')'
      text = trim(buf)
   end function address_describe

   !> Centre of a domain: mean of its contact points.
   subroutine domain_centre(geo, d, x, y)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: d
      real(wp), intent(out) :: x, y
      integer(ip) :: k, c, n
      x = 0.0_wp
      y = 0.0_wp
      n = geo%domains%count(d)
      do k = geo%domains%first(d), geo%domains%first(d) + n - 1
         c = geo%domains%ring(k)
         x = x + geo%contacts%x(c)
         y = y + geo%contacts%y(c)
      end do
      if (n > 0) then
         x = x/n
         y = y/n
      end if
   end subroutine domain_centre

   !> Value at offset `off` of the record of entity `id` of `kind` (Section 6.1
   !> tables). `name` is the manual's parameter name; found .false. for an
   !> offset this reimplementation does not keep (pointers of the linked
   !> lists, unused words). Address-valued words (KNB, KB1, KD1, KCOR, KZG)
   !> return the address of the entity they point to.
   subroutine address_field(geo, kind, id, off, name, value, found, fluid)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      integer(ip), intent(in) :: id, off
      character(len=:), allocatable, intent(out) :: name
      real(wp), intent(out) :: value
      logical, intent(out) :: found
      type(fluid_t), intent(in), optional :: fluid
      real(wp), allocatable :: rec(:)
      real(wp) :: fl(2)
      found = .false.
      fl = 0.0_wp
      value = 0.0_wp
      name = ''
      ! the record image of the entity, offset 0 first, and the names of its words
      select case (kind)
      case (ak_block)
         associate (b => geo%blocks)
            rec = [merge(3.0_wp, 1.0_wp, b%fdef(id)), 0.0_wp, 0.0_wp, real(b%material(id), wp), &
                   real(b%cons(id), wp), merge(1.0_wp, 0.0_wp, b%fixed(id)), 0.0_wp, b%xc(id), b%yc(id), &
                   b%vx(id), b%vy(id), b%vr(id), b%area(id), b%mass(id), b%inertia(id), 0.0_wp, &
                   b%fx(id), b%fy(id), b%fm(id), b%lx(id), b%ly(id)]
         end associate
         call pick(block_words)
      case (ak_corner)
         associate (c => geo%corners)
            rec = [0.0_wp, 0.0_wp, 0.0_wp, addr_at(geo%blocks%addr, geo%blocks%n, c%block(id)), 0.0_wp, &
                   c%x(id), c%y(id), c%rx(id), c%ry(id), c%radius(id)]
         end associate
         call pick(corner_words)
      case (ak_contact)
         if (present(fluid)) fl = [value_at(fluid%aperture, fluid%nc, id), value_at(fluid%q, fluid%nc, id)]
         associate (c => geo%contacts)
            rec = [5.0_wp, 0.0_wp, addr_at(geo%blocks%addr, geo%blocks%n, c%block1(id)), &
                   addr_at(geo%blocks%addr, geo%blocks%n, c%block2(id)), 0.0_wp, 0.0_wp, &
                   addr_at(geo%domains%addr, geo%domains%n, c%dom1(id)), &
                   addr_at(geo%domains%addr, geo%domains%n, c%dom2(id)), &
                   real(c%jmat(id), wp), real(c%jcons(id), wp), 0.0_wp, c%x(id), c%y(id), 0.0_wp, 0.0_wp, &
                   c%state%us(id), c%state%un(id), c%state%fs(id), c%state%fn(id), real(c%kind(id), wp), &
                   fl(1), fl(2), c%length(id), joint_state_value(c%state%phi_eff, id), c%nx(id), c%ny(id), &
                   0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, joint_state_value(c%state%reversal, id), &
                   joint_state_value(c%state%dus_old, id)]
         end associate
         call pick(contact_words)
      case (ak_domain)
         if (present(fluid)) then
            fl(1) = value_at(fluid%p, fluid%nd, id)
            if (allocated(fluid%fixed) .and. id <= fluid%nd) fl(2) = merge(1.0_wp, 0.0_wp, fluid%fixed(id))
         end if
         rec = [6.0_wp, 0.0_wp, 0.0_wp, geo%domains%area(id), fl(1), 0.0_wp, fl(2)]
         call pick(domain_words)
      case (ak_gridpoint)
         associate (g => geo%gridpoints)
            rec = [0.0_wp, addr_at(geo%corners%addr, geo%corners%n, g%corner(id)), 0.0_wp, g%x(id), g%y(id), &
                   g%vx(id), g%vy(id), g%fx(id), g%fy(id), g%mass(id), 0.0_wp, g%ux(id), g%uy(id)]
         end associate
         call pick(gridpoint_words)
      case (ak_zone)
         associate (z => geo%zones)
            rec = [0.0_wp, addr_at(geo%gridpoints%addr, geo%gridpoints%n, z%g1(id)), &
                   addr_at(geo%gridpoints%addr, geo%gridpoints%n, z%g2(id)), &
                   addr_at(geo%gridpoints%addr, geo%gridpoints%n, z%g3(id)), 0.0_wp, &
                   z%sxx(id), z%sxy(id), z%syy(id), 0.0_wp, 0.0_wp, real(z%state(id), wp)]
         end associate
         call pick(zone_words)
      end select
   contains
      !> The word at offset `off` when the table names it.
      subroutine pick(words)
         character(len=*), intent(in) :: words(0:)
         if (off < 0 .or. off > ubound(words, 1)) return
         if (words(off) == '') return
         name = trim(words(off))
         value = rec(off + 1)
         found = .true.
      end subroutine pick
      !> Address of entity i of a list of n (0: none).
      real(wp) function addr_at(addr, n, i)
         integer(ip), intent(in) :: addr(:), n, i
         addr_at = 0.0_wp
         if (i > 0 .and. i <= n) addr_at = real(addr(i), wp)
      end function addr_at
      !> a(i) of a list of n, 0 when the list is not kept.
      real(wp) function value_at(a, n, i)
         real(wp), allocatable, intent(in) :: a(:)
         integer(ip), intent(in) :: n, i
         value_at = 0.0_wp
         if (allocated(a) .and. i <= n) value_at = a(i)
      end function value_at
   end subroutine address_field

   !> RSET / ISET: store `value` at offset `off` of entity `id` of `kind`.
   !> Only words that are state (not derived each step from other words) can
   !> be set; `msg` is empty on success, else says why not.
   subroutine address_set_field(model, kind, id, off, value, msg)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: kind
      integer(ip), intent(in) :: id, off
      real(wp), intent(in) :: value
      character(len=:), allocatable, intent(out) :: msg
      msg = ''
      ! one case per settable word, keyed by kind and offset
      associate (geo => model%geometry, bl => model%geometry%blocks, ct => model%geometry%contacts%state, &
                 gp => model%geometry%gridpoints, zn => model%geometry%zones)
         select case (merge(100*kind + int(off), -1, off >= 0 .and. off < 100))
         case (100*ak_block + 3); bl%material(id) = nint(value)
         case (100*ak_block + 4); bl%cons(id) = nint(value)
         case (100*ak_block + 5); bl%fixed(id) = nint(value) /= 0
         case (100*ak_block + 9); bl%vx(id) = value
         case (100*ak_block + 10); bl%vy(id) = value
         case (100*ak_block + 11); bl%vr(id) = value
         case (100*ak_block + 19); bl%lx(id) = value
         case (100*ak_block + 20); bl%ly(id) = value
         case (100*ak_contact + 8); geo%contacts%jmat(id) = nint(value)
         case (100*ak_contact + 9)
            ! the contact list keeps jcons in one byte (issue 23)
            if (value < -0.5_wp .or. value >= huge(0_i1) + 0.5_wp) then
               msg = 'takes a JCONS number (1, 2, 3 or 5)'
            else
               geo%contacts%jcons(id) = int(nint(value), i1)
            end if
         case (100*ak_contact + 15); ct%us(id) = value
         case (100*ak_contact + 16); ct%un(id) = value
         case (100*ak_contact + 17); ct%fs(id) = value
         case (100*ak_contact + 18); ct%fn(id) = value
         case (100*ak_contact + 23)
            call joint_state_jcons3(geo%contacts)
            ct%phi_eff(id) = value
         case (100*ak_contact + 30)
            call joint_state_jcons3(geo%contacts)
            ct%reversal(id) = value
         case (100*ak_contact + 31)
            call joint_state_jcons3(geo%contacts)
            ct%dus_old(id) = value
         case (100*ak_domain + 4)
            msg = 'can be read but not set'
            if (allocated(model%fluid)) then
               if (id <= model%fluid%nd) then
                  model%fluid%p(id) = value
                  msg = ''
               end if
            end if
         case (100*ak_gridpoint + 5); gp%vx(id) = value
         case (100*ak_gridpoint + 6); gp%vy(id) = value
         case (100*ak_gridpoint + 11); gp%ux(id) = value
         case (100*ak_gridpoint + 12); gp%uy(id) = value
         case (100*ak_zone + 5); zn%sxx(id) = value
         case (100*ak_zone + 6); zn%sxy(id) = value
         case (100*ak_zone + 7); zn%syy(id) = value
         case default
            msg = 'can be read but not set'
         end select
      end associate
   end subroutine address_set_field

end module model_address
