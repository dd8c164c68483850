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
   use core_kinds, only: wp, ip, i8
   use core_sort, only: sort_order
   use model_geometry, only: geometry_t
   use model_state, only: model_t
   use model_fluid, only: fluid_t
   implicit none
   private
   public :: address_sync, address_entity, address_locate, address_field
   public :: address_set_field, address_kind_name, address_describe, address_or_id
   public :: ak_block, ak_corner, ak_contact, ak_domain, ak_gridpoint, ak_zone, nak
   public :: record_length, address_split, address_ensure

   integer, parameter :: ak_block = 1, ak_corner = 2, ak_contact = 3, ak_domain = 4
   integer, parameter :: ak_gridpoint = 5, ak_zone = 6, nak = 6
   !> Record lengths of Section 6.1 (NVBL, NVCR, NVCN, NVDO, NVGP, NVZO).
   integer(ip), parameter :: record_length(nak) = [23_ip, 13_ip, 32_ip, 8_ip, 12_ip, 12_ip]
   character(len=9), parameter :: kind_names(nak) = [character(len=9) :: 'block', 'corner', &
      'contact', 'domain', 'gridpoint', 'zone']

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
      integer(ip) :: i, b, k
      logical :: all
      all = .true.
      if (present(blocks_only)) all = .not. blocks_only
      call ensure_arrays(geo)
      ! 1. free what is gone, keep what is re-created
      do i = 1, geo%blocks%n
         if (.not. geo%blocks%live(i) .and. geo%blocks%addr(i) > 0) then
            call junk_push(geo, geo%blocks%addr(i), record_length(ak_block))
            geo%blocks%addr(i) = 0
         end if
      end do
      do i = 1, geo%gridpoints%n
         if (.not. geo%gridpoints%live(i) .and. geo%gridpoints%addr(i) > 0) then
            call junk_push(geo, geo%gridpoints%addr(i), record_length(ak_gridpoint))
            geo%gridpoints%addr(i) = 0
         end if
      end do
      do i = 1, geo%zones%n
         if (.not. geo%zones%live(i) .and. geo%zones%addr(i) > 0) then
            call junk_push(geo, geo%zones%addr(i), record_length(ak_zone))
            geo%zones%addr(i) = 0
         end if
      end do
      call match_positions(geo, ak_corner)
      if (all) then
         call match_positions(geo, ak_contact)
         call match_domains(geo)
      end if
      ! 2. new records, in the order of the module header
      do i = 1, geo%blocks%n
         if (geo%blocks%live(i) .and. geo%blocks%addr(i) == 0) &
            geo%blocks%addr(i) = take(geo, record_length(ak_block))
      end do
      do i = 1, geo%corners%n
         if (geo%corners%live(i) .and. geo%corners%addr(i) == 0) &
            geo%corners%addr(i) = take(geo, record_length(ak_corner))
      end do
      if (geo%ia%outer == 0 .and. geo%block_created) geo%ia%outer = take(geo, record_length(ak_domain))
      if (all) then
         do i = 1, geo%contacts%n
            if (geo%contacts%live(i) .and. geo%contacts%addr(i) == 0) &
               geo%contacts%addr(i) = take(geo, record_length(ak_contact))
         end do
         do i = 1, geo%domains%n
            if (.not. geo%domains%live(i)) cycle
            if (geo%domains%outer(i)) then
               if (geo%ia%outer == 0) geo%ia%outer = take(geo, record_length(ak_domain))
               geo%domains%addr(i) = geo%ia%outer
            else if (geo%domains%addr(i) == 0) then
               geo%domains%addr(i) = take(geo, record_length(ak_domain))
            end if
         end do
      end if
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         do k = geo%blocks%gfirst(b), geo%blocks%gfirst(b) + geo%blocks%ngp(b) - 1
            if (geo%gridpoints%live(k) .and. geo%gridpoints%addr(k) == 0) &
               geo%gridpoints%addr(k) = take(geo, record_length(ak_gridpoint))
         end do
         do k = geo%blocks%zfirst(b), geo%blocks%zfirst(b) + geo%blocks%nzone(b) - 1
            if (geo%zones%live(k) .and. geo%zones%addr(k) == 0) &
               geo%zones%addr(k) = take(geo, record_length(ak_zone))
         end do
      end do
      ! 3. remember this state for the next synchronisation
      call remember(geo, all)
   end subroutine address_sync

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
      if (geo%blocks%addr(b) == 0) geo%blocks%addr(b) = take(geo, record_length(ak_block))
      if (geo%blocks%addr(newb) == 0) geo%blocks%addr(newb) = take(geo, record_length(ak_block))
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
         if (geo%corners%addr(c) == 0) geo%corners%addr(c) = take(geo, record_length(ak_corner))
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
      if (.not. allocated(geo%ia%tab_addr)) then
         allocate (geo%ia%tab_addr(0, nak), geo%ia%tab_b1(0, nak), geo%ia%tab_b2(0, nak), &
                   geo%ia%tab_x(0, nak), geo%ia%tab_y(0, nak), geo%ia%tab_key(0, nak))
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
   integer(ip) function take(geo, len) result(a)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: len
      integer(ip) :: j
      do j = geo%ia%njunk, 1, -1
         if (geo%ia%junk_len(j) == len) then
            a = geo%ia%junk_addr(j)
            geo%ia%junk_addr(j:geo%ia%njunk - 1) = geo%ia%junk_addr(j + 1:geo%ia%njunk)
            geo%ia%junk_len(j:geo%ia%njunk - 1) = geo%ia%junk_len(j + 1:geo%ia%njunk)
            geo%ia%njunk = geo%ia%njunk - 1
            return
         end if
      end do
      a = geo%ia%mfree
      geo%ia%mfree = geo%ia%mfree + len
   end function take

   subroutine junk_push(geo, a, len)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: a, len
      integer(ip), allocatable :: t1(:), t2(:)
      if (.not. allocated(geo%ia%junk_addr)) allocate (geo%ia%junk_addr(16), geo%ia%junk_len(16))
      if (geo%ia%njunk >= size(geo%ia%junk_addr) .or. geo%ia%njunk >= size(geo%ia%junk_len)) then
         allocate (t1(max(16, 2*size(geo%ia%junk_addr))), t2(max(16, 2*size(geo%ia%junk_addr))))
         t1(1:geo%ia%njunk) = geo%ia%junk_addr(1:geo%ia%njunk)
         t2(1:geo%ia%njunk) = geo%ia%junk_len(1:geo%ia%njunk)
         call move_alloc(t1, geo%ia%junk_addr)
         call move_alloc(t2, geo%ia%junk_len)
      end if
      geo%ia%njunk = geo%ia%njunk + 1
      geo%ia%junk_addr(geo%ia%njunk) = a
      geo%ia%junk_len(geo%ia%njunk) = len
   end subroutine junk_push

   !> Corners and contacts: a live entity without address takes the record of
   !> an entity of the last synchronisation that is gone, at the same place
   !> (corners: same block preferred; contacts: the same two blocks). Records
   !> of gone entities not taken over return to the junk list.
   subroutine match_positions(geo, kind)
      type(geometry_t), intent(inout) :: geo
      integer, intent(in) :: kind
      integer(ip) :: nt, n, i, j, lo, hi, mid, best, a(1), dcx
      integer(ip), allocatable :: perm(:), p2(:), inuse(:)
      real(wp), allocatable :: kx(:), ky(:)
      logical, allocatable :: avail(:)
      real(wp) :: h, x, y, d, dbest, cs, qx, qy
      integer(ip) :: b1, b2
      logical :: pref, bpref, lv(1)
      nt = geo%ia%ntab(kind)
      if (kind == ak_corner) then
         n = geo%corners%n
      else
         n = geo%contacts%n
      end if
      ! records still owned by a live entity
      if (n > 0) then
         inuse = pack(entity_addr(1_ip, n), entity_live(1_ip, n) .and. entity_addr(1_ip, n) > 0)
      else
         allocate (inuse(0))
      end if
      call sort_int(inuse)
      allocate (avail(nt))
      do j = 1, nt
         avail(j) = .not. contains_sorted(inuse, geo%ia%tab_addr(j, kind))
      end do
      ! table entries sorted by cell (cx, cy) of size 2h: a match lies in
      ! one of the 3 x 3 cells around the query's (many corners share one x
      ! along a joint, so a sort by x alone would scan them all)
      h = 1.0e-6_wp*max(geo%extent, 1.0_wp) + 10.0_wp*geo%tol
      cs = 2.0_wp*h
      if (nt > 0) then
         allocate (perm(nt), p2(nt), kx(nt), ky(nt))
         kx = real(floor(geo%ia%tab_x(1:nt, kind)/cs, i8), wp)
         ky = real(floor(geo%ia%tab_y(1:nt, kind)/cs, i8), wp)
         call sort_order(ky, p2)
         call sort_order(kx(p2), perm)
         perm = p2(perm)
         kx = kx(perm)
         ky = ky(perm)
      end if
      do i = 1, n
         if (nt == 0) exit
         lv = entity_live(i, i)
         if (.not. lv(1)) cycle
         a = entity_addr(i, i)
         if (a(1) > 0) cycle
         call entity_key(i, x, y, b1, b2)
         qx = real(floor(x/cs, i8), wp)
         qy = real(floor(y/cs, i8), wp)
         best = 0
         dbest = huge(1.0_wp)
         bpref = .false.
         do dcx = -1, 1
            ! first entry with (kx, ky) >= (qx + dcx, qy - 1)
            lo = 1
            hi = nt + 1
            do while (lo < hi)
               mid = (lo + hi)/2
               if (kx(mid) < qx + dcx .or. (kx(mid) == qx + dcx .and. ky(mid) < qy - 1)) then
                  lo = mid + 1
               else
                  hi = mid
               end if
            end do
            do mid = lo, nt
               if (kx(mid) /= qx + dcx .or. ky(mid) > qy + 1) exit
               j = perm(mid)
               if (.not. avail(j)) cycle
               if (abs(geo%ia%tab_x(j, kind) - x) > h .or. abs(geo%ia%tab_y(j, kind) - y) > h) cycle
               if (kind == ak_contact) then
                  if (.not. ((geo%ia%tab_b1(j, kind) == b1 .and. geo%ia%tab_b2(j, kind) == b2) .or. &
                             (geo%ia%tab_b1(j, kind) == b2 .and. geo%ia%tab_b2(j, kind) == b1))) cycle
                  pref = .true.
               else
                  pref = geo%ia%tab_b1(j, kind) == b1
               end if
               d = hypot(geo%ia%tab_x(j, kind) - x, geo%ia%tab_y(j, kind) - y)
               if ((pref .and. .not. bpref) .or. ((pref .eqv. bpref) .and. d < dbest)) then
                  best = j
                  dbest = d
                  bpref = pref
               end if
            end do
         end do
         if (best > 0) then
            avail(best) = .false.
            call set_addr(i, geo%ia%tab_addr(best, kind))
         end if
      end do
      do j = 1, nt
         if (avail(j)) call junk_push(geo, geo%ia%tab_addr(j, kind), record_length(kind))
      end do
   contains
      pure function entity_addr(i1, i2) result(a)
         integer(ip), intent(in) :: i1, i2
         integer(ip) :: a(i2 - i1 + 1)
         if (kind == ak_corner) then
            a = geo%corners%addr(i1:i2)
         else
            a = geo%contacts%addr(i1:i2)
         end if
      end function entity_addr
      pure function entity_live(i1, i2) result(l)
         integer(ip), intent(in) :: i1, i2
         logical :: l(i2 - i1 + 1)
         if (kind == ak_corner) then
            l = geo%corners%live(i1:i2)
         else
            l = geo%contacts%live(i1:i2)
         end if
      end function entity_live
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

   !> Domains are rebuilt whole; a domain keeps the record of the domain of the
   !> last synchronisation with the same key: its first contact end, the
   !> smallest (contact address, side) on its ring.
   subroutine match_domains(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: nt, j, d, lo, hi, mid
      integer(i8), allocatable :: key(:)
      integer(ip), allocatable :: perm(:)
      logical, allocatable :: avail(:)
      nt = geo%ia%ntab(ak_domain)
      call domain_keys(geo, key)
      allocate (avail(nt), perm(nt))
      avail = .true.
      ! table keys in ascending order (keys are exact in real(wp) below 2**53)
      if (nt > 0) call sort_order(real(geo%ia%tab_key(1:nt, ak_domain), wp), perm)
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) cycle
         if (key(d) == huge(1_i8) .or. nt == 0) cycle
         lo = 1
         hi = nt + 1
         do while (lo < hi)
            mid = (lo + hi)/2
            if (geo%ia%tab_key(perm(mid), ak_domain) < key(d)) then
               lo = mid + 1
            else
               hi = mid
            end if
         end do
         do mid = lo, nt
            j = perm(mid)
            if (geo%ia%tab_key(j, ak_domain) /= key(d)) exit
            if (avail(j)) then
               geo%domains%addr(d) = geo%ia%tab_addr(j, ak_domain)
               avail(j) = .false.
               exit
            end if
         end do
      end do
      do j = 1, nt
         if (avail(j)) call junk_push(geo, geo%ia%tab_addr(j, ak_domain), record_length(ak_domain))
      end do
   end subroutine match_domains

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

   subroutine remember(geo, all)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in) :: all
      integer(ip) :: m, i, n
      integer(i8), allocatable :: key(:)
      m = max(geo%corners%n, geo%contacts%n, geo%domains%n, 1_ip)
      if (size(geo%ia%tab_addr, 1) < m) call grow_tables(geo, m)
      n = 0
      do i = 1, geo%corners%n
         if (.not. geo%corners%live(i)) cycle
         n = n + 1
         geo%ia%tab_addr(n, ak_corner) = geo%corners%addr(i)
         geo%ia%tab_b1(n, ak_corner) = geo%corners%block(i)
         geo%ia%tab_b2(n, ak_corner) = 0
         geo%ia%tab_x(n, ak_corner) = geo%corners%x(i)
         geo%ia%tab_y(n, ak_corner) = geo%corners%y(i)
      end do
      geo%ia%ntab(ak_corner) = n
      if (.not. all) return
      n = 0
      do i = 1, geo%contacts%n
         if (.not. geo%contacts%live(i)) cycle
         n = n + 1
         geo%ia%tab_addr(n, ak_contact) = geo%contacts%addr(i)
         geo%ia%tab_b1(n, ak_contact) = geo%contacts%block1(i)
         geo%ia%tab_b2(n, ak_contact) = geo%contacts%block2(i)
         geo%ia%tab_x(n, ak_contact) = geo%contacts%x(i)
         geo%ia%tab_y(n, ak_contact) = geo%contacts%y(i)
      end do
      geo%ia%ntab(ak_contact) = n
      call domain_keys(geo, key)
      n = 0
      do i = 1, geo%domains%n
         if (.not. geo%domains%live(i) .or. geo%domains%outer(i)) cycle
         n = n + 1
         geo%ia%tab_addr(n, ak_domain) = geo%domains%addr(i)
         geo%ia%tab_key(n, ak_domain) = key(i)
      end do
      geo%ia%ntab(ak_domain) = n
   end subroutine remember

   !> Match tables of at least m rows, keeping their contents.
   subroutine grow_tables(geo, m)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: m
      integer(ip), allocatable :: ta(:, :), t1(:, :), t2(:, :)
      real(wp), allocatable :: tx(:, :), ty(:, :)
      integer(i8), allocatable :: tk(:, :)
      integer(ip) :: k
      allocate (ta(m, nak), t1(m, nak), t2(m, nak), tx(m, nak), ty(m, nak), tk(m, nak))
      ta = 0; t1 = 0; t2 = 0; tx = 0.0_wp; ty = 0.0_wp; tk = 0_i8
      k = size(geo%ia%tab_addr, 1)
      if (k > 0) then
         ta(1:k, :) = geo%ia%tab_addr
         t1(1:k, :) = geo%ia%tab_b1
         t2(1:k, :) = geo%ia%tab_b2
         tx(1:k, :) = geo%ia%tab_x
         ty(1:k, :) = geo%ia%tab_y
         tk(1:k, :) = geo%ia%tab_key
      end if
      call move_alloc(ta, geo%ia%tab_addr)
      call move_alloc(t1, geo%ia%tab_b1)
      call move_alloc(t2, geo%ia%tab_b2)
      call move_alloc(tx, geo%ia%tab_x)
      call move_alloc(ty, geo%ia%tab_y)
      call move_alloc(tk, geo%ia%tab_key)
   end subroutine grow_tables

   subroutine sort_int(a)
      integer(ip), intent(inout) :: a(:)
      integer(ip), allocatable :: p(:)
      if (size(a) < 2) return
      allocate (p(size(a)))
      call sort_order(a, p)
      a = a(p)
   end subroutine sort_int

   pure logical function contains_sorted(a, v) result(found)
      integer(ip), intent(in) :: a(:), v
      integer :: lo, hi, mid
      found = .false.
      lo = 1
      hi = size(a)
      do while (lo <= hi)
         mid = (lo + hi)/2
         if (a(mid) == v) then
            found = .true.
            return
         else if (a(mid) < v) then
            lo = mid + 1
         else
            hi = mid - 1
         end if
      end do
   end function contains_sorted

   !> The live entity of `kind` whose record starts at address `a` (0: none).
   integer(ip) function address_entity(geo, kind, a) result(id)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      integer(ip), intent(in) :: a
      integer(ip) :: i
      id = 0
      if (a <= 0) return
      select case (kind)
      case (ak_block)
         do i = 1, geo%blocks%n
            if (geo%blocks%live(i) .and. geo%blocks%addr(i) == a) id = i
         end do
      case (ak_corner)
         do i = 1, geo%corners%n
            if (geo%corners%live(i) .and. geo%corners%addr(i) == a) id = i
         end do
      case (ak_contact)
         do i = 1, geo%contacts%n
            if (geo%contacts%live(i) .and. geo%contacts%addr(i) == a) id = i
         end do
      case (ak_domain)
         do i = 1, geo%domains%n
            if (geo%domains%live(i) .and. geo%domains%addr(i) == a) id = i
         end do
      case (ak_gridpoint)
         do i = 1, geo%gridpoints%n
            if (geo%gridpoints%live(i) .and. geo%gridpoints%addr(i) == a) id = i
         end do
      case (ak_zone)
         do i = 1, geo%zones%n
            if (geo%zones%live(i) .and. geo%zones%addr(i) == a) id = i
         end do
      end select
   end function address_entity

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
      select case (kind)
      case (ak_block)
         if (n <= geo%blocks%n) then
            if (geo%blocks%live(n)) id = n
         end if
      case (ak_corner)
         if (n <= geo%corners%n) then
            if (geo%corners%live(n)) id = n
         end if
      case (ak_contact)
         if (n <= geo%contacts%n) then
            if (geo%contacts%live(n)) id = n
         end if
      case (ak_domain)
         if (n <= geo%domains%n) then
            if (geo%domains%live(n)) id = n
         end if
      end select
      if (id > 0) how = 'id'
   end subroutine address_or_id

   !> The live entity whose record holds location `a` (kind 0: none) and the
   !> offset of `a` in it.
   subroutine address_locate(geo, a, kind, id, off)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: a
      integer, intent(out) :: kind
      integer(ip), intent(out) :: id, off
      integer :: k
      integer(ip) :: i
      kind = 0
      id = 0
      off = 0
      do k = 1, nak
         i = address_entity(geo, k, a)
         if (i > 0) then
            kind = k
            id = i
            return
         end if
      end do
      call scan(ak_block, geo%blocks%n, geo%blocks%live, geo%blocks%addr)
      if (kind > 0) return
      call scan(ak_corner, geo%corners%n, geo%corners%live, geo%corners%addr)
      if (kind > 0) return
      call scan(ak_contact, geo%contacts%n, geo%contacts%live, geo%contacts%addr)
      if (kind > 0) return
      call scan(ak_domain, geo%domains%n, geo%domains%live, geo%domains%addr)
      if (kind > 0) return
      call scan(ak_gridpoint, geo%gridpoints%n, geo%gridpoints%live, geo%gridpoints%addr)
      if (kind > 0) return
      call scan(ak_zone, geo%zones%n, geo%zones%live, geo%zones%addr)
   contains
      subroutine scan(k_, n_, live_, addr_)
         integer, intent(in) :: k_
         integer(ip), intent(in) :: n_
         logical, intent(in) :: live_(:)
         integer(ip), intent(in) :: addr_(:)
         integer(ip) :: j
         do j = 1, n_
            if (.not. live_(j) .or. addr_(j) <= 0) cycle
            if (a >= addr_(j) .and. a < addr_(j) + record_length(k_)) then
               kind = k_
               id = j
               off = a - addr_(j)
               return
            end if
         end do
      end subroutine scan
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
      found = .true.
      value = 0.0_wp
      name = ''
      block
         select case (kind)
         case (ak_block)
            associate (b => geo%blocks)
               select case (off)
               case (0); name = 'type'; value = merge(3.0_wp, 1.0_wp, b%fdef(id))
               case (3); name = 'KMAT'; value = real(b%material(id), wp)
               case (4); name = 'KCONS'; value = real(b%cons(id), wp)
               case (5); name = 'KBCOD'; value = merge(1.0_wp, 0.0_wp, b%fixed(id))
               case (7); name = 'KX'; value = b%xc(id)
               case (8); name = 'KY'; value = b%yc(id)
               case (9); name = 'KXD'; value = b%vx(id)
               case (10); name = 'KYD'; value = b%vy(id)
               case (11); name = 'KTD'; value = b%vr(id)
               case (12); name = 'KAREA'; value = b%area(id)
               case (13); name = 'KBM'; value = b%mass(id)
               case (14); name = 'KBI'; value = b%inertia(id)
               case (16); name = 'KBFX'; value = b%fx(id)
               case (17); name = 'KBFY'; value = b%fy(id)
               case (18); name = 'KBFT'; value = b%fm(id)
               case (19); name = 'KXL'; value = b%lx(id)
               case (20); name = 'KYL'; value = b%ly(id)
               case default; found = .false.
               end select
            end associate
         case (ak_corner)
            associate (c => geo%corners)
               select case (off)
               case (3); name = 'KNB'; value = real(geo%blocks%addr(c%block(id)), wp)
               case (5); name = 'KXP'; value = c%x(id)
               case (6); name = 'KYP'; value = c%y(id)
               case (7); name = 'KXCP'; value = c%rx(id)
               case (8); name = 'KYCP'; value = c%ry(id)
               case (9); name = 'KRAD'; value = c%radius(id)
               case default; found = .false.
               end select
            end associate
         case (ak_contact)
            associate (c => geo%contacts)
               select case (off)
               case (0); name = 'MCON'; value = 5.0_wp
               case (2); name = 'KB1'; value = real(geo%blocks%addr(c%block1(id)), wp)
               case (3); name = 'KB2'; value = real(geo%blocks%addr(c%block2(id)), wp)
               case (6); name = 'KD1'; value = real(dom_addr(c%dom1(id)), wp)
               case (7); name = 'KD2'; value = real(dom_addr(c%dom2(id)), wp)
               case (8); name = 'KCM'; value = real(c%jmat(id), wp)
               case (9); name = 'KCC'; value = real(c%jcons(id), wp)
               case (11); name = 'KXC'; value = c%x(id)
               case (12); name = 'KYC'; value = c%y(id)
               case (15); name = 'KCS'; value = c%state%us(id)
               case (16); name = 'KCN'; value = c%state%un(id)
               case (17); name = 'KCFS'; value = c%state%fs(id)
               case (18); name = 'KCFN'; value = c%state%fn(id)
               case (19); name = 'KCCOD'; value = real(c%kind(id), wp)
               case (20); name = 'KCAP'; value = fluid_contact(1)
               case (21); name = 'KCQ'; value = fluid_contact(2)
               case (22); name = 'KCL'; value = c%length(id)
               case (23); name = 'KGAM'; value = c%state%phi_eff(id)
               case (24); name = 'KCNX'; value = c%nx(id)
               case (25); name = 'KCNY'; value = c%ny(id)
               case (30); name = 'KCJREV'; value = c%state%reversal(id)
               case (31); name = 'KCJDS'; value = c%state%dus_old(id)
               case default; found = .false.
               end select
            end associate
         case (ak_domain)
            select case (off)
            case (0); name = 'MDOM'; value = 6.0_wp
            case (3); name = 'KDAR'; value = geo%domains%area(id)
            case (4); name = 'KPP'; value = fluid_domain(1)
            case (6); name = 'KDCOD'; value = fluid_domain(2)
            case default; found = .false.
            end select
         case (ak_gridpoint)
            associate (g => geo%gridpoints)
               select case (off)
               case (1); name = 'KCOR'
                  value = 0.0_wp
                  if (g%corner(id) > 0) value = real(geo%corners%addr(g%corner(id)), wp)
               case (3); name = 'KXG'; value = g%x(id)
               case (4); name = 'KYG'; value = g%y(id)
               case (5); name = 'KXDG'; value = g%vx(id)
               case (6); name = 'KYDG'; value = g%vy(id)
               case (7); name = 'KGFX'; value = g%fx(id)
               case (8); name = 'KGFY'; value = g%fy(id)
               case (9); name = 'KGPM'; value = g%mass(id)
               case (11); name = 'KGUX'; value = g%ux(id)
               case (12); name = 'KGUY'; value = g%uy(id)
               case default; found = .false.
               end select
            end associate
         case (ak_zone)
            associate (z => geo%zones)
               select case (off)
               case (1); name = 'KZG'; value = real(geo%gridpoints%addr(z%g1(id)), wp)
               case (2); name = 'KZG+1'; value = real(geo%gridpoints%addr(z%g2(id)), wp)
               case (3); name = 'KZG+2'; value = real(geo%gridpoints%addr(z%g3(id)), wp)
               case (5); name = 'KZS11'; value = z%sxx(id)
               case (6); name = 'KZS12'; value = z%sxy(id)
               case (7); name = 'KZS22'; value = z%syy(id)
               case (10); name = 'KZPLAS'; value = real(z%state(id), wp)
               case default; found = .false.
               end select
            end associate
         case default
            found = .false.
         end select
      end block
   contains
      integer(ip) function dom_addr(d)
         integer(ip), intent(in) :: d
         dom_addr = 0
         if (d > 0 .and. d <= geo%domains%n) dom_addr = geo%domains%addr(d)
      end function dom_addr
      real(wp) function fluid_contact(which)
         integer, intent(in) :: which
         fluid_contact = 0.0_wp
         if (.not. present(fluid)) return
         if (id > fluid%nc) return
         if (which == 1) then
            if (allocated(fluid%aperture)) fluid_contact = fluid%aperture(id)
         else
            if (allocated(fluid%q)) fluid_contact = fluid%q(id)
         end if
      end function fluid_contact
      real(wp) function fluid_domain(which)
         integer, intent(in) :: which
         fluid_domain = 0.0_wp
         if (.not. present(fluid)) return
         if (id > fluid%nd) return
         if (which == 1) then
            if (allocated(fluid%p)) fluid_domain = fluid%p(id)
         else
            if (allocated(fluid%fixed)) fluid_domain = merge(1.0_wp, 0.0_wp, fluid%fixed(id))
         end if
      end function fluid_domain
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
      associate (geo => model%geometry)
         select case (kind)
         case (ak_block)
            select case (off)
            case (3); geo%blocks%material(id) = nint(value)
            case (4); geo%blocks%cons(id) = nint(value)
            case (5); geo%blocks%fixed(id) = nint(value) /= 0
            case (9); geo%blocks%vx(id) = value
            case (10); geo%blocks%vy(id) = value
            case (11); geo%blocks%vr(id) = value
            case (19); geo%blocks%lx(id) = value
            case (20); geo%blocks%ly(id) = value
            case default; msg = 'can be read but not set'
            end select
         case (ak_contact)
            select case (off)
            case (8); geo%contacts%jmat(id) = nint(value)
            case (9); geo%contacts%jcons(id) = nint(value)
            case (15); geo%contacts%state%us(id) = value
            case (16); geo%contacts%state%un(id) = value
            case (17); geo%contacts%state%fs(id) = value
            case (18); geo%contacts%state%fn(id) = value
            case (23); geo%contacts%state%phi_eff(id) = value
            case (30); geo%contacts%state%reversal(id) = value
            case (31); geo%contacts%state%dus_old(id) = value
            case default; msg = 'can be read but not set'
            end select
         case (ak_domain)
            if (off == 4 .and. allocated(model%fluid)) then
               if (id <= model%fluid%nd) then
                  model%fluid%p(id) = value
                  return
               end if
            end if
            msg = 'can be read but not set'
         case (ak_gridpoint)
            select case (off)
            case (5); geo%gridpoints%vx(id) = value
            case (6); geo%gridpoints%vy(id) = value
            case (11); geo%gridpoints%ux(id) = value
            case (12); geo%gridpoints%uy(id) = value
            case default; msg = 'can be read but not set'
            end select
         case (ak_zone)
            select case (off)
            case (5); geo%zones%sxx(id) = value
            case (6); geo%zones%sxy(id) = value
            case (7); geo%zones%syy(id) = value
            case default; msg = 'can be read but not set'
            end select
         case default
            msg = 'can be read but not set'
         end select
      end associate
   end subroutine address_set_field

end module model_address
