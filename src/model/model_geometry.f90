!> Block-geometry state of a UDEC model (manual Sections 3.3 and 4.2 II):
!> blocks, their corners, the contacts between blocks, the domains (voids)
!> bounded by contacts, and the set-up state of the geometry commands
!> (rounding length, minimum edge, JREGION, tunnels, partial cracks, seed).
!>
!> Each entity kind is a structure of arrays with integer cross-references.
!> The array index is the entity id printed by PRINT and accepted by
!> commands; block ids are never reused while a model lives (deleted or
!> replaced entries go dead); corner ids go dead the same way within a
!> command and are made dense again after it (model_compact: the live
!> corners renumbered 1..n in their old order). Contacts and domains are derived
!> data: a full rebuild (UPCON / UPDOM) renumbers them from 1 (contacts along
!> a Hilbert curve through their first blocks, contact_detection).
!>
!> Tolerance policy: one relative constant, `geometry_tol_rel` = 1e-9. When
!> the first block is created, `geometry%tol` = geometry_tol_rel * model
!> extent (the larger side of the first block's bounding box). Every
!> "is this point on that edge / are these two points the same" decision in
!> cutting, contact detection and domains uses `geometry%tol`; decisions
!> about what is too small for the mechanics (edges, areas) use the minimum
!> edge `geometry%edge_min` (EDGE, default twice the rounding length).
module model_geometry
   use core_kinds, only: wp, ip, i8, i1, l1
   use core_arrays, only: grow_array, grow_lists, list_capacity
   use model_zones, only: gridpoint_list_t, zone_list_t
   implicit none
   private
   public :: geometry_t, ia_state_t, ia_table_t, block_list_t, corner_list_t, contact_list_t, joint_state_t
   public :: domain_list_t, pending_list_t, tunnel_list_t, jplot_list_t, jplot_list_add
   public :: geometry_tol_rel, geometry_init
   public :: geometry_block_polygon, geometry_kill_block, block_contains_point, unzoned_block
   public :: geometry_set_seed, geometry_random
   public :: grow_blocks, grow_corners, kill_corners, geometry_release_slack
   public :: joint_state_jcons3, joint_state_ud, joint_state_value, block_sdef_fields
   public :: geometry_add_contact, geometry_add_pending, geometry_add_tunnel, geometry_permute_contacts
   public :: geometry_add_jplot
   public :: geometry_live_blocks, geometry_total_area
   public :: contact_side, contact_side_fraction, contact_side_gridpoints
   public :: geometry_refused_cuts
   public :: contact_corner1, contact_corner2, contact_edge1, contact_edge2

   !> The rounding length when no ROUND is given (manual Section 2.1: "the
   !> default rounding length = 0.5 units").
   real(wp), parameter, public :: round_default = 0.5_wp

   !> What a cut did (indices of geometry_t%cut_stats).
   integer(ip), parameter, public :: cut_made = 1       !< a block split in two
   integer(ip), parameter, public :: cut_snapped = 2    !< an end moved onto a corner
   integer(ip), parameter, public :: cut_bend_moved = 3 !< a bend of a crack path straightened
   integer(ip), parameter, public :: cut_touch = 4      !< ran along an edge or touched a corner
   integer(ip), parameter, public :: cut_refused_short = 5   !< would leave a short edge
   integer(ip), parameter, public :: cut_refused_sliver = 6  !< would leave a sliver
   integer(ip), parameter, public :: cut_refused_shape = 7   !< pieces not simple polygons
   integer(ip), parameter, public :: cut_sliver_merged = 8   !< a sliver merged into its neighbour
   integer(ip), parameter, public :: cut_sliver_deleted = 9  !< a sliver deleted (no longer done: read from older saves)
   integer(ip), parameter, public :: ncut_stats = 9

   !> Relative geometric tolerance: absolute tolerance = this * model extent.
   real(wp), parameter :: geometry_tol_rel = 1.0e-9_wp
   !> How far (relative to the model extent) the typed end of a cut (CRACK,
   !> SPLIT, a JSET or ARC trace) may lie inside a block and still be taken
   !> for a point of the edge it nearly reaches: coordinates typed to six
   !> significant digits or six decimals (a point computed on an inclined
   !> edge) miss it by up to 5e-7 of their size.
   real(wp), parameter, public :: geometry_end_rel = 1.0e-6_wp
   integer(i8), parameter :: default_seed = 12345_i8

   !> Blocks: a clockwise ring of corners each.
   !> The live mark and the FIX, FDEF and SDEF flags of blocks, the live
   !> marks of corners, contacts and domains (and of zones and gridpoints,
   !> model_zones) are one-byte logicals (`logical(l1)`; issue 23: about 45
   !> bytes a block at 100k blocks); save files keep them as 32-bit integers.
   type :: block_list_t
      integer(ip) :: n = 0                             !< high-water mark
      logical(l1), allocatable :: live(:)
      integer(ip), allocatable :: first_corner(:), ncorner(:)
      integer(ip), allocatable :: material(:), cons(:)
      real(wp), allocatable :: area(:), xc(:), yc(:)    !< area > 0, centroid
      real(wp), allocatable :: xmin(:), xmax(:), ymin(:), ymax(:)   !< bounding box
      ! rigid-block mechanics (issue 4); velocities at t - dt/2 between steps
      real(wp), allocatable :: mass(:), inertia(:)      !< about the centroid
      real(wp), allocatable :: vx(:), vy(:), vr(:)      !< centroid velocity, angular velocity
      real(wp), allocatable :: ux(:), uy(:), rot(:)     !< accumulated displacement, rotation
      real(wp), allocatable :: fx(:), fy(:), fm(:)      !< force and moment sums of one step
      real(wp), allocatable :: lx(:), ly(:)             !< LOAD: static centroid load
      logical(l1), allocatable :: fixed(:)                  !< FIX: velocities held
      ! fully-deformable blocks (issue 6, model_zones): zones and gridpoints
      ! of a block are contiguous slices of the zone and gridpoint lists
      logical(l1), allocatable :: fdef(:)                   !< CHANGE FDEF / GENERATE
      integer(ip), allocatable :: zfirst(:), nzone(:)   !< zones (nzone 0: not zoned)
      integer(ip), allocatable :: gfirst(:), ngp(:)     !< gridpoints
      integer(ip), allocatable :: addr(:)               !< 1989 IA address (model_address; 0: none yet)
      ! simply-deformable blocks (CHANGE SDEF, engine_sdef): uniform strain
      ! (exy the tensor shear), its rate, the internal stress (tension
      ! positive) and the applied first moments of one step
      ! (qxx = sum fx rx, qyy = sum fy ry, qxy = sum (fx ry + fy rx)/2).
      ! The twelve reals exist (as long as the list, zero-filled) only once a
      ! block is made SDEF (block_sdef_fields): 96 bytes a block otherwise
      ! left out (issue 23); read only where sdef(b) is true
      logical(l1), allocatable :: sdef(:)
      real(wp), allocatable :: exx(:), eyy(:), exy(:), dxx(:), dyy(:), dxy(:)
      real(wp), allocatable :: sxx(:), syy(:), sxy(:), qxx(:), qyy(:), qxy(:)
      integer(ip), allocatable :: bstate(:)             !< CONS 4: 4 fractured (KBPLAS), else 0
   end type block_list_t

   !> Corners: ring links (clockwise `next`), owning block, rounding circle.
   type :: corner_list_t
      integer(ip) :: n = 0
      logical(l1), allocatable :: live(:)
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: block(:), next(:), prev(:)
      real(wp), allocatable :: rx(:), ry(:), radius(:)  !< rounding circle (Fig 3-3d)
      real(wp), allocatable :: ux(:), uy(:)             !< accumulated displacement
      integer(ip), allocatable :: gp(:)                 !< gridpoint of an FDEF block's corner, else 0
      integer(ip), allocatable :: addr(:)               !< 1989 IA address (model_address)
   end type corner_list_t

   !> Per-contact state the joint laws read and write (structure of arrays).
   !> Sign conventions (manual 4.1): fn compression positive, un opening
   !> positive; fs and us along the contact tangent t = (-ny, nx).
   type :: joint_state_t
      real(wp), allocatable :: fn(:), fs(:)      !< normal and shear force
      real(wp), allocatable :: un(:), us(:)      !< accumulated normal and shear displacement
      !> state bits (slip, tension, fractured): one byte a contact (issue 23);
      !> save files keep them as 32-bit integers
      integer(i1), allocatable :: flags(:)
      !> dilation ridden up (opening, length): the part of the geometric gap
      !> that the joint's asperities fill (JDIL while slipping, JCONS 3's
      !> Eq. 18); the contact is open when gap - ud exceeds the closing tolerance.
      !> Allocated (as long as the other fields, zero-filled) when a contact
      !> group first dilates or takes JCONS 3 (joint_state_ud), else left out
      !> (8 bytes a contact, issue 23): it is 0 where it is left out; read it
      !> through joint_state_value
      real(wp), allocatable :: ud(:)
      !> JCONS 3 only: allocated (as long as the other fields, zero-filled) when a
      !> contact first takes that law (joint_state_jcons3), else left out (24
      !> bytes a contact); read them through joint_state_value
      real(wp), allocatable :: phi_eff(:)        !< JCONS 3: effective friction angle
      real(wp), allocatable :: reversal(:)       !< JCONS 3: factor r of Eq. 13
      real(wp), allocatable :: dus_old(:)        !< JCONS 3: previous shear increment
   end type joint_state_t

   !> Contacts. kind 1 corner-corner, 2 corner(block1)-edge(block2),
   !> 3 edge(block1)-corner(block2). An edge is named by the corner it starts
   !> from (clockwise). Normal points from block1 into block2.
   !> kind and jcons are one-byte codes (issue 23: 6 bytes a contact fewer);
   !> save files keep them as 32-bit integers.
   type :: contact_list_t
      integer(ip) :: n = 0
      logical(l1), allocatable :: live(:)
      integer(ip), allocatable :: block1(:), block2(:)
      integer(i1), allocatable :: kind(:), jcons(:)
      !> the contact's feature on block1 and on block2: a corner id, or the
      !> corner an edge starts from, as `kind` says (issue 23: two ids a
      !> contact instead of four, of which two were always 0, 8 bytes a
      !> contact slot). Read corner1/corner2/edge1/edge2 through
      !> contact_corner1 .. contact_edge2 (0 where the kind has none).
      integer(ip), allocatable :: end1(:), end2(:)
      integer(ip), allocatable :: jmat(:), dom1(:), dom2(:)
      real(wp), allocatable :: x(:), y(:), nx(:), ny(:), length(:)
      real(wp), allocatable :: gap(:)                   !< signed gap of the rounded
                                                        !< surfaces (> 0 open, < 0 overlap)
      type(joint_state_t) :: state                      !< forces, displacements, flags
      integer(ip), allocatable :: addr(:)               !< 1989 IA address (model_address)
   end type contact_list_t

   !> Domains: cyclic contact lists stored contiguously in `ring`.
   !> live and outer are one-byte logicals (issue 23: 6 bytes a domain, about
   !> three domains a block); save files keep them as 32-bit integers.
   type :: domain_list_t
      integer(ip) :: n = 0
      logical(l1), allocatable :: live(:), outer(:)
      real(wp), allocatable :: area(:)                 !< > 0 void, < 0 outer region
      integer(ip), allocatable :: first(:), count(:)   !< slice of `ring`
      integer(ip) :: nring = 0
      integer(ip), allocatable :: ring(:)
      integer(ip), allocatable :: addr(:)              !< 1989 IA address (model_address)
   end type domain_list_t

   !> The 1989 program's main array IA as bookkeeping (manual Section 6.1):
   !> every entity gets the address its record would have had, computed when
   !> it is created (model_address); nothing is stored at those addresses.
   !> `tab` remembers the records handed out at the last synchronisation,
   !> so that an entity the set-up code re-creates (a corner of a re-cut
   !> block, a contact of a rebuilt contact list, a rebuilt domain) keeps
   !> its record, as the 1989 linked lists kept theirs.
   !> One kind's match table (ia_state_t): address, owner block (or block1),
   !> second block (contacts only), position (x, y: corners and contacts) or
   !> domain key (key: domains only); a kind allocates only its own columns.
   !> Domains: a row per live domain of the last synchronisation (the list
   !> is rebuilt whole). Corners and contacts: `synced(i)` = 1 marks entity
   !> i (1..nsynced) live at the last synchronisation; one that is gone
   !> since keeps address, block(s) and position in its own dead slot (a
   !> slot is never reused: corners and contacts are appended), so only the
   !> marks are kept, one byte an entity. The rows hold only the contacts a
   !> rebuild of the contact list is about to overwrite (model_address,
   !> `address_keep_contacts`; nsynced is then 0). Issue 23: copies of all
   !> live corners and contacts were 30 MB at 100k blocks.
   type :: ia_table_t
      integer(ip), allocatable :: addr(:), b1(:), b2(:)
      real(wp), allocatable :: x(:), y(:)
      integer(i8), allocatable :: key(:)
      integer(ip) :: nsynced = 0
      integer(i1), allocatable :: synced(:)
   end type ia_table_t

   type :: ia_state_t
      integer(ip) :: mfree = 1                   !< next never-used address (MFREE)
      integer(ip) :: outer = 0                   !< record of the outer domain (0: none yet)
      integer(ip) :: njunk = 0                   !< freed records (junk list, Fig. 6-5)
      integer(ip), allocatable :: junk_addr(:), junk_len(:)
      !> records of the last synchronisation, per kind (index: model_address's
      !> kind; only corners, contacts and domains have one): ntab rows each
      integer(ip) :: ntab(6) = 0
      type(ia_table_t) :: tab(6)
   end type ia_state_t

   !> Crack segments that did not (yet) separate a block (manual 5.2.1).
   type :: pending_list_t
      integer(ip) :: n = 0
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
   end type pending_list_t

   !> Tunnel peripheries (polygons of n sides) that later cracks stop at.
   type :: tunnel_list_t
      integer(ip) :: n = 0
      real(wp), allocatable :: xc(:), yc(:), r(:)
      integer(ip), allocatable :: nside(:)
   end type tunnel_list_t

   !> Joint segments laid down between JPLOT START and STOP (manual 4.6): CRACK
   !> and JSET record the pieces of their joints that lie inside live blocks
   !> here instead of cutting the blocks, so the pattern can be plotted first.
   !> The joint-trace file of SET WRITE (manual 4.5: "writes 'scratch' joint
   !> file to RJOINT").
   character(len=*), parameter, public :: rjoint_file = 'RJOINT'

   type :: jplot_list_t
      logical :: on = .false.                           !< between JPLOT START and STOP
      integer(ip) :: n = 0
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
      integer(ip), allocatable :: block(:)              !< block the piece lies in
   end type jplot_list_t

   !> The whole block geometry of one model.
   type :: geometry_t
      type(block_list_t) :: blocks
      type(corner_list_t) :: corners
      type(contact_list_t) :: contacts
      type(domain_list_t) :: domains
      type(pending_list_t) :: pending
      type(tunnel_list_t) :: tunnels
      type(jplot_list_t) :: jplot
      type(gridpoint_list_t) :: gridpoints              !< FDEF blocks (model_zones)
      type(zone_list_t) :: zones
      type(ia_state_t) :: ia              !< 1989 addresses (model_address)
      real(wp) :: round = round_default   !< ROUND d
      real(wp) :: edge_min = 1.0_wp       !< EDGE emin (>= 2*round)
      logical :: edge_set = .false.       !< EDGE given: ROUND no longer resets it
      real(wp) :: tol = 0.0_wp            !< absolute tolerance (see module header)
      real(wp) :: extent = 0.0_wp         !< larger side of the first block's box
      real(wp) :: original_area = 0.0_wp  !< area of the BLOCK command's block
      real(wp) :: deleted_area = 0.0_wp   !< area removed by DELETE and clean-up
      logical :: block_created = .false.
      logical :: has_jregion = .false.
      real(wp) :: jregion_x(4) = 0.0_wp, jregion_y(4) = 0.0_wp
      integer(i8) :: rng_state = 0_i8
      integer(ip) :: jmat_default = 0     !< SET JMATDF (0: block material)
      integer(ip) :: jcons_default = 2    !< SET JCONDF
      logical :: contacts_valid = .false.
      logical :: domains_valid = .false.
      integer(ip) :: outer_domain = 0
      !> running counts of what the cutting commands did (index: cut_made ..);
      !> a command's summary is the difference across it
      integer(ip) :: cut_stats(ncut_stats) = 0
      !> cuts refused so far (block, reason, first and last point of the
      !> path), so that a pending chain tried again with every later crack
      !> that touches its block is counted once (saved from schema 16)
      real(wp), allocatable :: refused_keys(:, :)
      integer(ip) :: nrefused_keys = 0
      logical :: mechanical = .false.     !< cycling has begun: contacts carry state and
                                          !< are updated in place, never rebuilt
   end type geometry_t

contains

   !> Contact c's corner on block1 (kinds 1 and 2), corner on block2 (kinds 1
   !> and 3), edge on block1 (kind 3), edge on block2 (kind 2): the contact's
   !> end1 or end2 where its kind has that feature, else 0.
   pure integer(ip) function contact_corner1(ct, c) result(id)
      type(contact_list_t), intent(in) :: ct
      integer(ip), intent(in) :: c
      id = merge(0_ip, ct%end1(c), ct%kind(c) == 3_i1)
   end function contact_corner1

   pure integer(ip) function contact_corner2(ct, c) result(id)
      type(contact_list_t), intent(in) :: ct
      integer(ip), intent(in) :: c
      id = merge(0_ip, ct%end2(c), ct%kind(c) == 2_i1)
   end function contact_corner2

   pure integer(ip) function contact_edge1(ct, c) result(id)
      type(contact_list_t), intent(in) :: ct
      integer(ip), intent(in) :: c
      id = merge(ct%end1(c), 0_ip, ct%kind(c) == 3_i1)
   end function contact_edge1

   pure integer(ip) function contact_edge2(ct, c) result(id)
      type(contact_list_t), intent(in) :: ct
      integer(ip), intent(in) :: c
      id = merge(ct%end2(c), 0_ip, ct%kind(c) == 2_i1)
   end function contact_edge2

   !> Cuts refused since the model began (short edge, sliver, bad shape); a
   !> cut along an existing edge or through a corner only is not refused.
   pure integer(ip) function geometry_refused_cuts(geo) result(n)
      type(geometry_t), intent(in) :: geo
      n = geo%cut_stats(cut_refused_short) + geo%cut_stats(cut_refused_sliver) + &
          geo%cut_stats(cut_refused_shape)
   end function geometry_refused_cuts

   !> Reset to an empty model with default settings (START / NEW).
   subroutine geometry_init(geo)
      type(geometry_t), intent(out) :: geo
      call grow_blocks(geo%blocks, 64_ip)
      call grow_corners(geo%corners, 256_ip)
      call geometry_set_seed(geo, default_seed)
   end subroutine geometry_init

   !> SET SEED n: the same seed gives the same sequence on every platform.
   subroutine geometry_set_seed(geo, seed)
      type(geometry_t), intent(inout) :: geo
      integer(i8), intent(in) :: seed
      integer(ip) :: i
      real(wp) :: r
      ! xorshift64 needs a non-zero state; mixing the seed with a constant
      ! keeps small seeds (1, 2, 3) from giving correlated first draws
      geo%rng_state = ieor(seed, int(z'2545F4914F6CDD1D', i8))
      if (geo%rng_state == 0_i8) geo%rng_state = int(z'2545F4914F6CDD1D', i8)
      do i = 1, 8
         r = geometry_random(geo)
      end do
   end subroutine geometry_set_seed

   !> Uniform deviate in [0,1) from xorshift64 (Marsaglia 2003); shifts and
   !> exclusive-or only, so there is no integer overflow to depend on.
   function geometry_random(geo) result(r)
      type(geometry_t), intent(inout) :: geo
      real(wp) :: r
      integer(i8) :: s
      s = geo%rng_state
      s = ieor(s, ishft(s, 13))
      s = ieor(s, ishft(s, -7))
      s = ieor(s, ishft(s, 17))
      geo%rng_state = s
      r = real(ishft(s, -11), wp)*2.0_wp**(-53)
   end function geometry_random

   !> Corner coordinates (and ids) of block `id` in clockwise order.
   subroutine geometry_block_polygon(geo, id, x, y, ids)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: id
      real(wp), allocatable, intent(out) :: x(:), y(:)
      integer(ip), allocatable, intent(out), optional :: ids(:)
      integer(ip) :: i, n, c
      n = geo%blocks%ncorner(id)
      allocate (x(n), y(n))
      if (present(ids)) allocate (ids(n))
      c = geo%blocks%first_corner(id)
      do i = 1, n
         x(i) = geo%corners%x(c)
         y(i) = geo%corners%y(c)
         if (present(ids)) ids(i) = c
         c = geo%corners%next(c)
      end do
   end subroutine geometry_block_polygon

   !> Crossing-number test of (x, y) against the corner ring of block b;
   !> a point on an edge may go either way.
   pure logical function block_contains_point(geo, b, x, y) result(inside)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      real(wp), intent(in) :: x, y
      integer(ip) :: c, cn, k
      inside = .false.
      c = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         cn = geo%corners%next(c)
         associate (x1 => geo%corners%x(c), y1 => geo%corners%y(c), &
                    x2 => geo%corners%x(cn), y2 => geo%corners%y(cn))
            if ((y1 > y) .neqv. (y2 > y)) then
               if (x < x1 + (y - y1)*(x2 - x1)/(y2 - y1)) inside = .not. inside
            end if
         end associate
         c = cn
      end do
   end function block_contains_point

   !> Block b is live and has no zones (rigid or simply-deformable): the blocks
   !> whose temperature the thermal mesh carries at their centroid (Fig. 7-4).
   pure logical function unzoned_block(geo, b) result(unzoned)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      unzoned = .false.
      if (b < 1 .or. b > geo%blocks%n) return
      if (.not. geo%blocks%live(b)) return
      unzoned = geo%blocks%nzone(b) == 0
   end function unzoned_block

   !> Mark block `id` and its corners dead; its area is counted as deleted.
   subroutine geometry_kill_block(geo, id)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      if (.not. geo%blocks%live(id)) return
      geo%deleted_area = geo%deleted_area + geo%blocks%area(id)
      call kill_corners(geo, id)
      call kill_zoning(geo, id)
      geo%blocks%live(id) = .false.
      geo%contacts_valid = .false.
      geo%domains_valid = .false.
   end subroutine geometry_kill_block

   !> Append a contact; returns its id. Derived fields left at defaults.
   subroutine geometry_add_contact(geo, id)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(out) :: id
      associate (c => geo%contacts)
         if (.not. allocated(c%live)) call grow_contacts(c, 256_ip)
         if (c%n >= size(c%live)) call grow_contacts(c, list_capacity(size(c%live), c%n + 1_ip))
         c%n = c%n + 1
         id = c%n
         c%live(id) = .true.
         c%block1(id) = 0
         c%block2(id) = 0
         c%kind(id) = 0
         c%end1(id) = 0
         c%end2(id) = 0
         c%jmat(id) = 0
         c%jcons(id) = 0
         if (allocated(c%dom1)) then
            c%dom1(id) = 0
            c%dom2(id) = 0
         end if
         c%x(id) = 0.0_wp
         c%y(id) = 0.0_wp
         c%nx(id) = 0.0_wp
         c%ny(id) = 0.0_wp
         c%length(id) = 0.0_wp
         c%gap(id) = 0.0_wp
         c%state%fn(id) = 0.0_wp
         c%state%fs(id) = 0.0_wp
         c%state%un(id) = 0.0_wp
         c%state%us(id) = 0.0_wp
         c%state%flags(id) = 0
         if (allocated(c%state%ud)) c%state%ud(id) = 0.0_wp
         if (allocated(c%state%phi_eff)) then
            c%state%phi_eff(id) = 0.0_wp
            c%state%reversal(id) = 0.0_wp
            c%state%dus_old(id) = 0.0_wp
         end if
         c%addr(id) = 0
      end associate
   end subroutine geometry_add_contact

   !> Remember a crack segment that has not (yet) separated a block.
   subroutine geometry_add_pending(geo, x1, y1, x2, y2)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2
      associate (p => geo%pending)
         if (.not. allocated(p%x1)) then
            call grow_lists(0_ip, 16_ip, p%x1, p%y1, p%x2, p%y2)
         else if (p%n >= size(p%x1)) then
            call grow_lists(p%n, 2_ip*size(p%x1), p%x1, p%y1, p%x2, p%y2)
         end if
         p%n = p%n + 1
         p%x1(p%n) = x1; p%y1(p%n) = y1; p%x2(p%n) = x2; p%y2(p%n) = y2
      end associate
   end subroutine geometry_add_pending

   !> Record a JPLOT joint piece lying inside block `block`.
   subroutine geometry_add_jplot(geo, x1, y1, x2, y2, block)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2
      integer(ip), intent(in) :: block
      call jplot_list_add(geo%jplot, x1, y1, x2, y2, block)
   end subroutine geometry_add_jplot

   !> Append a segment to a list of joint pieces (JPLOT, SET WRITE).
   subroutine jplot_list_add(j, x1, y1, x2, y2, block)
      type(jplot_list_t), intent(inout) :: j
      real(wp), intent(in) :: x1, y1, x2, y2
      integer(ip), intent(in) :: block
      integer(ip) :: m
      associate (j => j)
         if (.not. allocated(j%x1)) then
            m = 64
            call grow_lists(0_ip, m, j%x1, j%y1, j%x2, j%y2)
            call grow_array(j%block, 0_ip, m)
         else if (j%n >= size(j%x1)) then
            m = 2_ip*size(j%x1)
            call grow_lists(j%n, m, j%x1, j%y1, j%x2, j%y2)
            call grow_array(j%block, j%n, m)
         end if
         j%n = j%n + 1
         j%x1(j%n) = x1; j%y1(j%n) = y1; j%x2(j%n) = x2; j%y2(j%n) = y2
         j%block(j%n) = block
      end associate
   end subroutine jplot_list_add

   !> Remember a tunnel periphery.
   subroutine geometry_add_tunnel(geo, xc, yc, r, nside)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: xc, yc, r
      integer(ip), intent(in) :: nside
      integer(ip) :: n
      associate (tu => geo%tunnels)
         n = tu%n
         call grow_lists(n, n + 1, tu%xc, tu%yc, tu%r)
         call grow_array(tu%nside, n, n + 1)
         tu%n = n + 1
         tu%xc(n + 1) = xc
         tu%yc(n + 1) = yc
         tu%r(n + 1) = r
         tu%nside(n + 1) = nside
      end associate
   end subroutine geometry_add_tunnel

   !> Number of live blocks.
   pure function geometry_live_blocks(geo) result(n)
      type(geometry_t), intent(in) :: geo
      integer(ip) :: n
      n = 0
      if (geo%blocks%n > 0) n = count(geo%blocks%live(1:geo%blocks%n))
   end function geometry_live_blocks

   !> Sum of the areas of live blocks.
   pure function geometry_total_area(geo) result(a)
      type(geometry_t), intent(in) :: geo
      real(wp) :: a
      a = 0.0_wp
      if (geo%blocks%n > 0) a = sum(geo%blocks%area(1:geo%blocks%n), &
                                    mask=geo%blocks%live(1:geo%blocks%n))
   end function geometry_total_area

   !> Zones and gridpoints of block `id` go dead (DELETE of an FDEF block).
   subroutine kill_zoning(geo, id)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      integer(ip) :: k
      associate (b => geo%blocks)
         do k = b%zfirst(id), b%zfirst(id) + b%nzone(id) - 1
            geo%zones%live(k) = .false.
         end do
         do k = b%gfirst(id), b%gfirst(id) + b%ngp(id) - 1
            geo%gridpoints%live(k) = .false.
         end do
         b%nzone(id) = 0
         b%ngp(id) = 0
      end associate
   end subroutine kill_zoning

   subroutine kill_corners(geo, id)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      integer(ip) :: i, c
      c = geo%blocks%first_corner(id)
      do i = 1, geo%blocks%ncorner(id)
         geo%corners%live(c) = .false.
         c = geo%corners%next(c)
      end do
      geo%blocks%first_corner(id) = 0
      geo%blocks%ncorner(id) = 0
   end subroutine kill_corners

   !> Give back the empty slots of the block and corner lists (`lists` = 1),
   !> of the contact list (2) or of all three (3, the default) when more than
   !> a thirty-second of a list is empty: the list keeps its entries (same ids,
   !> same order) with a sixty-fourth (and 64) slots to spare, room for the
   !> contacts a CYCLE makes as blocks move (issue 23: a sixteenth to spare and
   !> an eighth empty before trimming left 45 000 empty contact slots, 6 MB, at
   !> 100k blocks). Called after detection (contact_refresh); a no-op when the
   !> lists are already tight, so it allocates nothing in a cycle.
   subroutine geometry_release_slack(geo, lists)
      type(geometry_t), intent(inout) :: geo
      integer, intent(in), optional :: lists
      integer :: which
      which = 3
      if (present(lists)) which = lists
      if (iand(which, 1) /= 0) then
         if (allocated(geo%blocks%live)) then
            if (slack(geo%blocks%n, size(geo%blocks%live, kind=ip))) &
               call grow_blocks(geo%blocks, tight(geo%blocks%n))
         end if
         if (allocated(geo%corners%live)) then
            if (slack(geo%corners%n, size(geo%corners%live, kind=ip))) &
               call grow_corners(geo%corners, tight(geo%corners%n))
         end if
      end if
      if (iand(which, 2) /= 0 .and. allocated(geo%contacts%live)) then
         if (slack(geo%contacts%n, size(geo%contacts%live, kind=ip))) &
            call grow_contacts(geo%contacts, tight(geo%contacts%n))
      end if
   contains
      pure logical function slack(n, cap)
         integer(ip), intent(in) :: n, cap
         slack = cap > tight(n) + n/64_ip
      end function slack
      pure integer(ip) function tight(n)
         integer(ip), intent(in) :: n
         tight = n + n/64_ip + 64_ip
      end function tight
   end subroutine geometry_release_slack

   subroutine grow_blocks(b, m)
      type(block_list_t), intent(inout) :: b
      integer(ip), intent(in) :: m
      call grow_lists(b%n, m, b%area, b%xc, b%yc, b%xmin, b%xmax, b%ymin, b%ymax, b%mass, &
                      b%inertia, b%vx, b%vy, b%vr, b%ux, b%uy, b%rot, b%fx)
      call grow_lists(b%n, m, b%fy, b%fm, b%lx, b%ly)
      call grow_lists(b%n, m, b%first_corner, b%ncorner, b%material, b%cons, b%zfirst, b%nzone, &
                      b%gfirst, b%ngp)
      call grow_lists(b%n, m, b%live, b%fixed, b%fdef, b%sdef)
      call grow_array(b%addr, b%n, m)
      if (allocated(b%exx)) &
         call grow_lists(b%n, m, b%exx, b%eyy, b%exy, b%dxx, b%dyy, b%dxy, b%sxx, b%syy, b%sxy, &
                         b%qxx, b%qyy, b%qxy)
      call grow_array(b%bstate, b%n, m)
   end subroutine grow_blocks

   !> The SDEF fields of the blocks (strain, its rate, stress, first moments)
   !> exist, as long as the block list (zero-filled: the state a block is made
   !> SDEF with). A model without SDEF blocks leaves them out.
   subroutine block_sdef_fields(b)
      type(block_list_t), intent(inout) :: b
      integer(ip) :: m
      if (allocated(b%exx)) return
      m = 0
      if (allocated(b%live)) m = size(b%live, kind=ip)
      allocate (b%exx(m), b%eyy(m), b%exy(m), b%dxx(m), b%dyy(m), b%dxy(m), b%sxx(m), b%syy(m), &
                b%sxy(m), b%qxx(m), b%qyy(m), b%qxy(m), source=0.0_wp)
   end subroutine block_sdef_fields

   subroutine grow_corners(c, m)
      type(corner_list_t), intent(inout) :: c
      integer(ip), intent(in) :: m
      call grow_lists(c%n, m, c%x, c%y, c%rx, c%ry, c%radius, c%ux, c%uy)
      call grow_lists(c%n, m, c%block, c%next, c%prev, c%gp)
      call grow_array(c%live, c%n, m)
      call grow_array(c%addr, c%n, m)
   end subroutine grow_corners

   !> The JCONS 3 fields of the joint state exist, as long as the contact
   !> list (zero-filled: the state a contact starts from).
   subroutine joint_state_jcons3(c)
      type(contact_list_t), intent(inout) :: c
      integer(ip) :: m
      if (allocated(c%state%phi_eff)) return
      m = contact_slots(c)
      allocate (c%state%phi_eff(m), c%state%reversal(m), c%state%dus_old(m), source=0.0_wp)
   end subroutine joint_state_jcons3

   !> The dilation ridden up (joint_state_t%ud) made for every contact slot,
   !> zero-filled, once a contact group dilates (JDIL > 0) or takes JCONS 3
   !> (contact_groups_build): the only laws that change it.
   subroutine joint_state_ud(c)
      type(contact_list_t), intent(inout) :: c
      if (allocated(c%state%ud)) return
      allocate (c%state%ud(contact_slots(c)), source=0.0_wp)
   end subroutine joint_state_ud

   !> Slots of the contact list (its capacity; 0 before the first contact).
   pure integer(ip) function contact_slots(c) result(m)
      type(contact_list_t), intent(in) :: c
      m = 0
      if (allocated(c%live)) m = size(c%live, kind=ip)
   end function contact_slots

   !> Entry i of a joint-state field that may be left out (ud; JCONS 3's
   !> phi_eff, reversal, dus_old): 0 when it is (no contact needed it).
   pure real(wp) function joint_state_value(a, i) result(v)
      real(wp), allocatable, intent(in) :: a(:)
      integer(ip), intent(in) :: i
      v = 0.0_wp
      if (allocated(a)) v = a(i)
   end function joint_state_value

   subroutine grow_contacts(c, m)
      type(contact_list_t), intent(inout) :: c
      integer(ip), intent(in) :: m
      logical :: doms
      ! dom1/dom2 given back by a dry CYCLE (contact_domains' domain_release)
      ! stay so until the domains are built again
      doms = allocated(c%dom1) .or. .not. allocated(c%live)
      call grow_lists(c%n, m, c%x, c%y, c%nx, c%ny, c%length, c%gap)
      call grow_lists(c%n, m, c%block1, c%block2, c%end1, c%end2, c%jmat)
      if (doms) call grow_lists(c%n, m, c%dom1, c%dom2)
      call grow_array(c%kind, c%n, m)
      call grow_array(c%jcons, c%n, m)
      call grow_array(c%live, c%n, m)
      call grow_array(c%state%fn, c%n, m)
      call grow_array(c%state%fs, c%n, m)
      call grow_array(c%state%un, c%n, m)
      call grow_array(c%state%us, c%n, m)
      call grow_array(c%state%flags, c%n, m)
      if (allocated(c%state%ud)) call grow_array(c%state%ud, c%n, m)
      if (allocated(c%state%phi_eff)) then
         call grow_array(c%state%phi_eff, c%n, m)
         call grow_array(c%state%reversal, c%n, m)
         call grow_array(c%state%dus_old, c%n, m)
      end if
      call grow_array(c%addr, c%n, m)
   end subroutine grow_contacts

   !> Renumber contacts 1..n: contact k takes what contact order(k) held
   !> (order a permutation of 1..n). Only for a list nothing else refers to
   !> yet (contact_rebuild, before the domains are built from it).
   subroutine geometry_permute_contacts(geo, order)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: order(:)
      integer(ip) :: n
      n = geo%contacts%n
      associate (c => geo%contacts)
         call permute_real(c%x); call permute_real(c%y)
         call permute_real(c%nx); call permute_real(c%ny)
         call permute_real(c%length); call permute_real(c%gap)
         call permute_int(c%block1); call permute_int(c%block2)
         call permute_int(c%end1); call permute_int(c%end2)
         call permute_int(c%jmat)
         if (allocated(c%dom1)) then
            call permute_int(c%dom1); call permute_int(c%dom2)
         end if
         call permute_int(c%addr)
         c%kind(1:n) = c%kind(order)
         c%jcons(1:n) = c%jcons(order)
         c%live(1:n) = c%live(order)
         call permute_real(c%state%fn); call permute_real(c%state%fs)
         call permute_real(c%state%un); call permute_real(c%state%us)
         if (allocated(c%state%ud)) call permute_real(c%state%ud)
         c%state%flags(1:n) = c%state%flags(order)
         if (allocated(c%state%phi_eff)) then
            call permute_real(c%state%phi_eff)
            call permute_real(c%state%reversal)
            call permute_real(c%state%dus_old)
         end if
      end associate
   contains
      subroutine permute_real(a)
         real(wp), intent(inout) :: a(:)
         a(1:n) = a(order)
      end subroutine permute_real
      subroutine permute_int(a)
         integer(ip), intent(inout) :: a(:)
         a(1:n) = a(order)
      end subroutine permute_int
   end subroutine geometry_permute_contacts

   !> The parts of side `side` (1: block1, 2: block2) of contact c: its
   !> corner (a corner-corner contact, or the corner side of a corner-edge
   !> contact; edge = other = 0), or the edge (its starting corner) and the
   !> other block's corner facing it (corner = 0), with `frac`, when given,
   !> contact_side_fraction of the two.
   !>
   !> The edge is the one the other corner's VERTEX projects onto, which may
   !> be the neighbour of the contact's edge across a corner without
   !> rounding (a gridpoint, or a vertex where a joint ends on the far side
   !> of a joint): the contact's edge is the one its rounded circle meets
   !> (contact_kinematics), and where a straight vertex lies within a
   !> rounding length of the corner, the circle's centre is beyond it while
   !> the vertex is not. The force then goes where the stretch of joint the
   !> contact stands for is (contact_lengths measures stretches between
   !> vertices), not all to the vertex between, with a couple for the
   !> offset along the joint (contact_force_pass) -- which a near-T junction
   !> (joints ending on a joint 4 cm apart) showed as 2e4 N out of balance.
   !> The walk goes on across as many such corners as lie between (a 0.25 m
   !> rounding over 6.5 cm zone edges: four); stopping after one put the
   !> force of a filled re-entrant corner's contact three gridpoints short
   !> of the vertex, 5.3e5 N out of balance after INSITU (campaign seed 35).
   pure subroutine contact_side(geo, c, side, corner, edge, other, frac)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      integer, intent(in) :: side
      integer(ip), intent(out) :: corner, edge, other
      real(wp), intent(out), optional :: frac
      real(wp) :: w, w2
      integer(ip) :: e2, step
      integer :: dir
      !> a vertex on the shared gridpoint of two edges projects to 0 on one
      !> and 1 on the other, give or take rounding: the tolerance keeps the
      !> neighbour edge from being refused for -1e-16 (which sent the force
      !> a whole edge away, to the far gridpoint of the contact's own edge)
      real(wp), parameter :: wtol = 1.0e-6_wp
      corner = 0
      edge = 0
      other = 0
      if (present(frac)) frac = 0.0_wp
      associate (ct => geo%contacts)
         if (side == 1) then
            if (ct%kind(c) == 3) then
               edge = contact_edge1(ct, c); other = contact_corner2(ct, c)
            else
               corner = contact_corner1(ct, c)
            end if
         else
            if (ct%kind(c) == 2) then
               edge = contact_edge2(ct, c); other = contact_corner1(ct, c)
            else
               corner = contact_corner2(ct, c)
            end if
         end if
      end associate
      if (edge == 0) return
      w = raw_fraction(geo, edge, other)
      ! from edge to edge across corners without rounding, one way only: a
      ! rounded corner spans as many gridpoints as fit in a rounding length
      ! (ROUND 0.25 over 6.5 cm zones: four), and its vertex can lie that
      ! many edges away from the edge its circle meets
      dir = 0
      do step = 1, geo%blocks%ncorner(geo%corners%block(edge))
         e2 = 0
         if (w < -wtol .and. dir <= 0 .and. geo%corners%radius(edge) <= 0.0_wp) then
            e2 = geo%corners%prev(edge)
            dir = -1
         else if (w > 1.0_wp + wtol .and. dir >= 0 .and. &
                  geo%corners%radius(geo%corners%next(edge)) <= 0.0_wp) then
            e2 = geo%corners%next(edge)
            dir = 1
         end if
         if (e2 <= 0) exit
         ! the neighbour edge if the vertex is nearer to it: within it, or
         ! (around a re-entrant gridpoint the vertex fills) beyond both,
         ! where the nearest point is the gridpoint they share, not the far
         ! end of the contact's edge
         w2 = raw_fraction(geo, e2, other)
         if (clamped_distance2(geo, e2, other, w2) > clamped_distance2(geo, edge, other, w)) exit
         edge = e2
         w = w2
      end do
      if (present(frac)) frac = min(max(w, 0.0_wp), 1.0_wp)
   end subroutine contact_side

   !> Squared distance from corner `other`'s vertex to the point of the edge
   !> starting at corner `edge` at fraction w clamped to [0, 1].
   pure real(wp) function clamped_distance2(geo, edge, other, w) result(d2)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: edge, other
      real(wp), intent(in) :: w
      integer(ip) :: q
      real(wp) :: t
      associate (co => geo%corners)
         q = co%next(edge)
         t = min(max(w, 0.0_wp), 1.0_wp)
         d2 = (co%x(edge) + t*(co%x(q) - co%x(edge)) - co%x(other))**2 + &
              (co%y(edge) + t*(co%y(q) - co%y(edge)) - co%y(other))**2
      end associate
   end function clamped_distance2

   !> Unclamped projection of corner `other`'s vertex on the edge starting
   !> at corner `edge`, as a fraction of the edge from its start.
   pure real(wp) function raw_fraction(geo, edge, other) result(w)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: edge, other
      integer(ip) :: q
      real(wp) :: ex, ey, l2
      associate (co => geo%corners)
         q = co%next(edge)
         ex = co%x(q) - co%x(edge)
         ey = co%y(q) - co%y(edge)
         l2 = ex*ex + ey*ey
         w = 0.0_wp
         if (l2 > 0.0_wp) w = ((co%x(other) - co%x(edge))*ex + (co%y(other) - co%y(edge))*ey)/l2
      end associate
   end function raw_fraction

   !> Where the vertex of corner `other` projects on the edge starting at
   !> corner `edge`, as a fraction of the edge from its start, in [0, 1].
   !> The vertex (the sharp corner the contact stands for), not the contact
   !> point: that lies on the rounding circle, a rounding length d along the
   !> edge from the vertex, so at the end of a joint (a joint crossing or the
   !> model boundary) d / L of a force would go to the next gridpoint and an
   !> INSITU-balanced model would not stay balanced (2 % at ROUND 0.02 and
   !> 1 m zones). At the switch to a corner-corner contact at the edge's end
   !> the vertex projects onto the end, so the fraction is continuous there.
   pure real(wp) function contact_side_fraction(geo, edge, other) result(w)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: edge, other
      w = min(max(raw_fraction(geo, edge, other), 0.0_wp), 1.0_wp)
   end function contact_side_fraction

   !> Gridpoints carrying side `side` of contact c on a fully-deformable
   !> block: the corner's gridpoint (gb = ga, w = 0), or the two end
   !> gridpoints of the edge, with w the weight of the end gridpoint gb
   !> (contact_side_fraction). Zero ids on a block without gridpoints.
   pure subroutine contact_side_gridpoints(geo, c, side, ga, gb, w)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      integer, intent(in) :: side
      integer(ip), intent(out) :: ga, gb
      real(wp), intent(out) :: w
      integer(ip) :: corner, edge, other
      call contact_side(geo, c, side, corner, edge, other, w)
      if (corner > 0) then
         ga = geo%corners%gp(corner)
         gb = ga
         return
      end if
      ga = geo%corners%gp(edge)
      gb = geo%corners%gp(geo%corners%next(edge))
   end subroutine contact_side_gridpoints

end module model_geometry
