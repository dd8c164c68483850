!> Geometry of a contact between rounded blocks (manual Section 3.3, Fig 3-3d):
!> gap, unit normal and contact point of one contact at the current block
!> positions, with the smooth change between corner-edge and corner-corner
!> contacts as blocks slide and rotate.
!>
!> A block's boundary is made of straight edge parts between the tangent
!> points of the corner circles, and the circle arcs themselves. A corner
!> with radius 0 (straight or re-entrant corner) is a point.
!>   corner c against edge e:  n = outward normal of e,
!>                             gap = (C_c - P_e) . n - r_c
!>   corner c against corner d: n along the line of the circle centres,
!>                             gap = |C_d - C_c| - r_c - r_d
!> A corner-edge contact whose corner centre projects beyond the straight
!> part of the edge becomes a corner-corner contact with the corner at that
!> end; a corner-corner contact whose centre line leaves the arc of either
!> corner (the cone between the outward normals of its two edges) becomes a
!> corner-edge contact with the edge on that side. At the switch both forms
!> give the same gap and normal, so the normal turns continuously.
!>
!> Contact kinds (model_geometry): 1 corner1-corner2, 2 corner1 (block1)
!> against edge2 (block2), 3 edge1 (block1) against corner2 (block2). The
!> normal points from block1 into block2.
!>
!> Edge frames: the contact pass of every step (contact_mechanics) first
!> computes the frame of every edge once (edge_frames_compute) and gives
!> them to contact_geometry, which otherwise computes one to four frames
!> per contact (a corner-corner contact tests both cones). The values are
!> those edge_frame gives, so results do not depend on which is used.
module contact_kinematics
   use core_kinds, only: wp, ip, i1, l1
   use model_geometry, only: geometry_t, block_contains_point
   implicit none
   private
   public :: contact_geometry, corner_nearest_feature, edge_frame, edge_frames_compute
   public :: corner_turn, corner_fills_reflex, length2

   !> Smallest outward turn (radians) of a re-entrant corner whose filling
   !> corner gets a contact with each of its two edges (corner_fills_reflex):
   !> 1 degree, far above the bending of a straight gridpoint of a deformed
   !> edge (strains of 1e-3 bend it by about 0.06 degree), so two zoned
   !> blocks meeting gridpoint to gridpoint along a joint keep one contact
   !> per gridpoint pair.
   real(wp), parameter, public :: reflex_min_turn = 1.7453292519943295e-2_wp
   !> bounds of length2's common range (the C library's): the library scales
   !> a longer side above 2**511 and a shorter side below 2**-459 (where the
   !> correction terms, about side**2 * 2**-53, would fall below the normal
   !> range), and a side below 2**-54 of the other is negligible; a longer
   !> side below 2**-511 is left to the library
   real(wp), parameter :: length2_large = 2.0_wp**511, length2_small = 2.0_wp**(-511)
   real(wp), parameter :: length2_tiny = 2.0_wp**(-459)
   real(wp), parameter :: length2_eps = 2.0_wp**(-54)
   public :: contact_geometry_all, contact_overlap_limit, contact_overlap_bound, overlap_judge
   !> contact_overlap_bound's codes: which bound set a contact's tolerance
   integer, parameter, public :: overlap_bound_ovtol = 0, overlap_bound_radii = 1, &
                                 overlap_bound_round = 2, overlap_bound_edge = 3, &
                                 overlap_bound_switch = 4
   !> A corner-edge contact's share of rc + rf (contact_overlap_limit): its
   !> switch to a corner-corner contact at the edge's end keeps the gap
   !> while the overlap is below rc + rf; a tenth is left for the steps
   !> between two judgements (a step closes a contact by well under 1 % of
   !> it: 2.5e-4 of 7.9e-2 on the new user's tunnel, docs/robustness.md).
   real(wp), parameter, public :: switch_fraction = 0.9_wp

contains

   !> Frames of the edges of every corner at the current positions:
   !> frame(1:4, e) = ux, uy, s0, s1 as edge_frame(geo, e) gives them (the
   !> same expressions; the normal is (-uy, ux)). `frame` has at least
   !> geo%corners%n columns.
   !> (The loop runs in edge_frames_kernel with explicit-shape dummies: the
   !> arrays' addresses stay in registers.) Corner ids are dense (model_compact),
   !> so the loop tests no liveness; a dead corner left in the list (a model
   !> that cannot compact yet) keeps its ring links and gets a frame no contact
   !> reads.
   !> `nthreads` > 1 (and enough corners): the corners are shared among that
   !> many OpenMP threads (each frame is its own corner's: same values).
   subroutine edge_frames_compute(geo, frame, nthreads)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(inout) :: frame(4, *)
      integer, intent(in), optional :: nthreads
      integer :: t, nchunk
      nchunk = 1
      if (present(nthreads)) then
         if (nthreads > 1 .and. geo%corners%n >= 8000) nchunk = 4*nthreads
      end if
      associate (co => geo%corners)
         if (nchunk == 1) then
            call edge_frames_kernel(1_ip, co%n, co%next, co%x, co%y, co%rx, co%ry, frame)
         else
            !$omp parallel do schedule(static) private(t)
            do t = 1, nchunk
               call edge_frames_kernel(1 + (t - 1)*co%n/nchunk, t*co%n/nchunk, co%next, &
                                       co%x, co%y, co%rx, co%ry, frame)
            end do
            !$omp end parallel do
         end if
      end associate
   end subroutine edge_frames_compute

   pure subroutine edge_frames_kernel(e0, n, next, x, y, rx, ry, frame)
      integer(ip), intent(in) :: e0, n
      integer(ip), intent(in) :: next(*)
      real(wp), intent(in) :: x(*), y(*), rx(*), ry(*)
      real(wp), intent(inout) :: frame(4, *)
      integer(ip) :: e
      real(wp) :: ux, uy, s0, s1
      do e = e0, n
         ! (into locals first: written straight into frame, each value was
         ! stored and loaded again)
         call edge_frame_of(e, next, x, y, rx, ry, ux, uy, s0, s1)
         frame(1, e) = ux
         frame(2, e) = uy
         frame(3, e) = s0
         frame(4, e) = s1
      end do
   end subroutine edge_frames_kernel

   !> The frame of the edge starting at corner e (edge_frame without the
   !> normal), from the corner arrays.
   pure subroutine edge_frame_of(e, next, x, y, rx, ry, ux, uy, s0, s1)
      integer(ip), intent(in) :: e
      integer(ip), intent(in) :: next(*)
      real(wp), intent(in) :: x(*), y(*), rx(*), ry(*)
      real(wp), intent(out) :: ux, uy, s0, s1
      integer(ip) :: q
      real(wp) :: l
      q = next(e)
      ux = x(q) - x(e)
      uy = y(q) - y(e)
      call unit_vector(ux, uy, l, 1.0_wp, 0.0_wp)    ! length2: sqrt(ux*ux + uy*uy) changes results
      s0 = (rx(e) - x(e))*ux + (ry(e) - y(e))*uy
      s1 = (rx(q) - x(e))*ux + (ry(q) - y(e))*uy
   end subroutine edge_frame_of

   !> (wx, wy) divided by its length `l` (length2); a vector of length 0 (or
   !> NaN) becomes (dx, dy).
   pure subroutine unit_vector(wx, wy, l, dx, dy)
      real(wp), intent(inout) :: wx, wy
      real(wp), intent(out) :: l
      real(wp), intent(in) :: dx, dy
      l = length2(wx, wy)
      if (l > 0.0_wp) then
         wx = wx/l
         wy = wy/l
      else
         wx = dx
         wy = dy
      end if
   end subroutine unit_vector

   !> Unit vector along the edge starting at corner `e`, its outward normal
   !> (left of the clockwise edge) and the straight part [s0, s1] measured
   !> from corner e along the edge (the tangent points of the end circles).
   pure subroutine edge_frame(geo, e, ux, uy, nx, ny, s0, s1)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: e
      real(wp), intent(out) :: ux, uy, nx, ny, s0, s1
      associate (co => geo%corners)
         call edge_frame_of(e, co%next, co%x, co%y, co%rx, co%ry, ux, uy, s0, s1)
      end associate
      nx = -uy
      ny = ux
   end subroutine edge_frame

   !> Where a direction (wx, wy) leaves the arc of corner d: 0 inside the
   !> cone of outward normals, -1 before the incoming edge's normal, +1
   !> beyond the outgoing edge's normal. `tol` is a small angle allowance.
   pure integer function cone_side(geo, d, wx, wy, tol, frame) result(side)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: d
      real(wp), intent(in) :: wx, wy, tol
      real(wp), intent(in), optional :: frame(4, *)
      real(wp) :: ux, uy, ax, ay, bx, by, s0, s1, ci, co
      integer(ip) :: p
      if (present(frame)) then
         p = geo%corners%prev(d)
         ax = -frame(2, p)
         ay = frame(1, p)
         bx = -frame(2, d)
         by = frame(1, d)
      else
         call edge_frame(geo, geo%corners%prev(d), ux, uy, ax, ay, s0, s1)
         call edge_frame(geo, d, ux, uy, bx, by, s0, s1)
      end if
      ! clockwise sweep from a (incoming normal) to b (outgoing normal)
      ci = ax*wy - ay*wx        ! > 0: w is counter-clockwise of a (before the arc)
      co = wx*by - wy*bx        ! > 0: w is clockwise of b (beyond the arc)
      side = 0
      if (ci > tol .and. co > tol) then
         ! re-entrant or straight corner with w outside on both sides: the
         ! nearer edge wins
         if (ci >= co) then
            side = -1
         else
            side = 1
         end if
      else if (ci > tol) then
         side = -1
      else if (co > tol) then
         side = 1
      end if
      ! w pointing into the block against both edge normals: the cross
      ! products above cannot see it when the corner is straight (a = b,
      ! both products 0, e.g. a gridpoint in the middle of a zoned edge) or
      ! re-entrant. This is the centre line of two overlapping radius-0
      ! corners, which has turned round: the edge whose normal it opposes
      ! more is the one that was crossed.
      if (side == 0 .and. ax*wx + ay*wy < 0.0_wp .and. bx*wx + by*wy < 0.0_wp) then
         if (ax*wx + ay*wy <= bx*wx + by*wy) then
            side = -1
         else
            side = 1
         end if
      end if
   end function cone_side

   !> Gap, normal (block1 -> block2) and point of contact `c`, switching its
   !> kind where the geometry requires (see module header). `tol` is the
   !> hysteresis length for the switches; `frame`, when given, the edge
   !> frames at the current positions (edge_frames_compute).
   subroutine contact_geometry(geo, c, tol, gap, nx, ny, px, py, frame)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: tol
      real(wp), intent(out) :: gap, nx, ny, px, py
      real(wp), intent(in), optional :: frame(4, *)
      !> a contact may walk from one feature to the next (corner, edge,
      !> corner of the next edge) as blocks slide; this bounds the walk
      integer, parameter :: npass = 8
      integer :: pass, side
      integer(ip) :: cc, e, d
      real(wp) :: ux, uy, ex, ey, s0, s1, s, wx, wy, dist, ta
      ta = 1.0e-9_wp
      do pass = 1, npass
         select case (geo%contacts%kind(c))
         case (2, 3)
            if (geo%contacts%kind(c) == 2) then
               cc = geo%contacts%end1(c); e = geo%contacts%end2(c)
            else
               cc = geo%contacts%end2(c); e = geo%contacts%end1(c)
            end if
            if (present(frame)) then
               ux = frame(1, e)
               uy = frame(2, e)
               ex = -uy
               ey = ux
               s0 = frame(3, e)
               s1 = frame(4, e)
            else
               call edge_frame(geo, e, ux, uy, ex, ey, s0, s1)
            end if
            s = (geo%corners%rx(cc) - geo%corners%x(e))*ux + (geo%corners%ry(cc) - geo%corners%y(e))*uy
            if (geo%corners%radius(cc) <= 0.0_wp) then
               ! a corner without rounding (a straight vertex: a gridpoint,
               ! or where a joint ends on this side of a joint; or a
               ! re-entrant one) meets the edge anywhere between its
               ! vertices. On the rounded part [0, s0) it would switch to
               ! corner-corner with the edge's rounded end corner and, the
               ! line of centres leaving its own (zero) arc, on to that
               ! corner against ITS edge: the contact of the other block's
               ! corner, a twin that drop_twins kills with its force. Found
               ! on a near-T junction (two finite joints ending on a joint
               ! 2 cm apart at ROUND 0.05): the vertex's contact, carrying
               ! INSITU's force for 0.74 m of joint, became the corner's
               ! and was dropped at the first scan, 8 MN out of balance.
               ! Against the edge's line it keeps its force where its
               ! stretch of joint is (contact_side_fraction: the vertex).
               s0 = 0.0_wp
               s1 = (geo%corners%x(geo%corners%next(e)) - geo%corners%x(e))*ux + &
                    (geo%corners%y(geo%corners%next(e)) - geo%corners%y(e))*uy
            end if
            if (pass == npass .and. (s < s0 - tol .or. s > s1 + tol)) then
               ! the switches did not settle: measure against the circle at
               ! the end of the edge the centre has passed, not against the
               ! edge's line (which would report a false overlap as deep as
               ! the block behind it)
               d = e
               if (s > s1 + tol) d = geo%corners%next(e)
               wx = geo%corners%rx(d) - geo%corners%rx(cc)
               wy = geo%corners%ry(d) - geo%corners%ry(cc)
               call unit_vector(wx, wy, dist, -ex, -ey)
               gap = dist - geo%corners%radius(cc) - geo%corners%radius(d)
               px = geo%corners%rx(cc) + wx*(geo%corners%radius(cc) + 0.5_wp*gap)
               py = geo%corners%ry(cc) + wy*(geo%corners%radius(cc) + 0.5_wp*gap)
               if (geo%contacts%kind(c) == 2) then
                  nx = wx; ny = wy
               else
                  nx = -wx; ny = -wy
               end if
               return
            end if
            if (s < s0 - tol .or. s > s1 + tol) then
               d = e
               if (s > s1 + tol) d = geo%corners%next(e)
               ! past an end of the edge: corner-corner with that end
               call set_feature(geo, c, 1_i1, merge(2, 1, geo%contacts%kind(c) == 2), d, 0_ip)
               cycle
            end if
            gap = (geo%corners%rx(cc) - geo%corners%x(e))*ex + &
                  (geo%corners%ry(cc) - geo%corners%y(e))*ey - geo%corners%radius(cc)
            ! point halfway between the corner circle and the edge line
            px = geo%corners%rx(cc) - ex*(geo%corners%radius(cc) + 0.5_wp*gap)
            py = geo%corners%ry(cc) - ey*(geo%corners%radius(cc) + 0.5_wp*gap)
            if (geo%contacts%kind(c) == 2) then
               nx = -ex; ny = -ey
            else
               nx = ex; ny = ey
            end if
            return
         case default
            cc = geo%contacts%end1(c)
            d = geo%contacts%end2(c)
            wx = geo%corners%rx(d) - geo%corners%rx(cc)
            wy = geo%corners%ry(d) - geo%corners%ry(cc)
            ! coincident centres (dist 0): keep the last normal
            call unit_vector(wx, wy, dist, geo%contacts%nx(c), geo%contacts%ny(c))
            if (.not. (dist > 0.0_wp) .and. wx == 0.0_wp .and. wy == 0.0_wp) wx = 1.0_wp
            if (pass < npass) then
               ! leaving the arc of corner2: corner1 against an edge of block2
               side = cone_side(geo, d, -wx, -wy, ta, frame)
               if (side /= 0) then
                  call set_feature(geo, c, 2_i1, 2, 0_ip, merge(geo%corners%prev(d), d, side < 0))
                  cycle
               end if
               side = cone_side(geo, cc, wx, wy, ta, frame)
               if (side /= 0) then
                  call set_feature(geo, c, 3_i1, 1, 0_ip, merge(geo%corners%prev(cc), cc, side < 0))
                  cycle
               end if
            end if
            gap = dist - geo%corners%radius(cc) - geo%corners%radius(d)
            nx = wx; ny = wy
            px = geo%corners%rx(cc) + wx*(geo%corners%radius(cc) + 0.5_wp*gap)
            py = geo%corners%ry(cc) + wy*(geo%corners%radius(cc) + 0.5_wp*gap)
            return
         end select
      end do
   end subroutine contact_geometry

   !> Contact c changes kind (1 corner-corner, 2 corner1-edge2, 3
   !> edge1-corner2): its feature on block `end` (1 or 2) becomes `corner`
   !> or `edge` (the other one 0).
   pure subroutine set_feature(geo, c, kind, end, corner, edge)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: c, corner, edge
      integer(i1), intent(in) :: kind
      integer, intent(in) :: end
      geo%contacts%kind(c) = kind
      if (end == 2) then
         geo%contacts%end2(c) = corner + edge
      else
         geo%contacts%end1(c) = corner + edge
      end if
   end subroutine set_feature

   !> Turn of the boundary at corner `c` (radians, in (-pi, pi]): negative
   !> where the clockwise outline turns right (a convex corner, interior
   !> angle pi + turn), positive at a re-entrant corner, 0 at a straight one.
   pure real(wp) function corner_turn(geo, c) result(t)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp) :: ax, ay, bx, by
      associate (co => geo%corners)
         ax = co%x(c) - co%x(co%prev(c))
         ay = co%y(c) - co%y(co%prev(c))
         bx = co%x(co%next(c)) - co%x(c)
         by = co%y(co%next(c)) - co%y(c)
      end associate
      t = atan2(ax*by - ay*bx, ax*bx + ay*by)
   end function corner_turn

   !> Corner `cc` fills the re-entrant corner `r` of another block: r is a
   !> point (radius 0) turning outward by more than reflex_min_turn, the two
   !> vertices lie within `tol` of each other and the corner angles add up
   !> to 360 degrees (within half reflex_min_turn), so cc's two edges lie
   !> along r's two edges -- the corner of a TUNNEL plug at a vertex of the
   !> ring. cc's rounded corner then touches both of r's edges, each along
   !> a stretch of its own (manual Section 3.3, Fig 3-3b and d: an edge-edge
   !> contact is two corner-edge contacts), and makes one contact with each
   !> edge; one contact per corner and block would leave one of the two
   !> stretches without its end contact.
   pure logical function corner_fills_reflex(geo, cc, r, tol) result(fills)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: cc, r
      real(wp), intent(in) :: tol
      real(wp) :: tr, tc
      fills = .false.
      if (cc <= 0 .or. r <= 0) return
      if (geo%corners%block(cc) == geo%corners%block(r)) return
      if (geo%corners%radius(r) > 0.0_wp) return
      if (length2(geo%corners%x(cc) - geo%corners%x(r), geo%corners%y(cc) - geo%corners%y(r)) > tol) &
         return
      tr = corner_turn(geo, r)
      if (tr <= reflex_min_turn) return
      tc = corner_turn(geo, cc)
      fills = abs(tc + tr) <= 0.5_wp*reflex_min_turn
   end function corner_fills_reflex
   !> contact_geometry of every live contact (the contact pass of a step),
   !> with the frames of edge_frames_compute: gap into gap_new(c), normal and
   !> point into the contact list. The common cases are written out here (a
   !> corner-edge contact whose corner stays over the straight part of its
   !> edge; a corner-corner contact whose centre line stays inside both arcs)
   !> with the expressions contact_geometry uses, so the results are the same
   !> to the last bit; any other contact (a switch of kind) goes through
   !> contact_geometry, which starts again from the unchanged contact.
   !> `bad`: the live contact, not `void`, with the largest overlap beyond
   !> `ovtol` (0 if none; the first of equal ones).
   !> The fast cases run in geometry_fast_kernel with the arrays as
   !> explicit-shape dummies (addresses in registers, not reloaded from the
   !> geometry's descriptors at each access); it stops at the first contact it
   !> cannot do, which is done here before the kernel goes on from the next.
   !> `nthreads` > 1: the contacts are shared among that many OpenMP threads
   !> in chunks (each contact's geometry is its own); the chunks' largest
   !> overlaps are compared in chunk order, so `bad` is the same contact.
   !> The tolerance of each contact (contact_overlap_limit) is at least
   !> the model's OVTOL, so the caller judges only when `bad` > 0, and then
   !> only those few contacts (overlap_judge).
   subroutine contact_geometry_all(geo, tol, frame, void, ovtol, gap_new, bad, nthreads)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: tol, ovtol
      real(wp), intent(in) :: frame(4, *)
      logical(l1), intent(in) :: void(:)
      real(wp), intent(inout) :: gap_new(:)
      integer(ip), intent(out) :: bad
      integer, intent(in), optional :: nthreads
      integer :: t, nchunk
      integer(ip), allocatable :: tbad(:)
      real(wp), allocatable :: tworst(:)
      real(wp) :: worst
      nchunk = 1
      if (present(nthreads)) nchunk = 4*max(1, nthreads)
      if (nchunk <= 4) then
         call contact_geometry_range(geo, 1_ip, geo%contacts%n, tol, frame, void, ovtol, gap_new, bad, worst)
      else
         allocate (tbad(nchunk), tworst(nchunk))
         !$omp parallel do schedule(static) private(t)
         do t = 1, nchunk
            call contact_geometry_range(geo, 1 + (t - 1)*geo%contacts%n/nchunk, t*geo%contacts%n/nchunk, &
                                        tol, frame, void, ovtol, gap_new, tbad(t), tworst(t))
         end do
         !$omp end parallel do
         bad = 0
         worst = ovtol
         do t = 1, nchunk
            if (tbad(t) > 0 .and. tworst(t) > worst) then
               worst = tworst(t)
               bad = tbad(t)
            end if
         end do
      end if
   end subroutine contact_geometry_all

   !> Of the live, not void, contacts overlapping by more than `ovtol`, the
   !> one with the largest overlap beyond its own tolerance
   !> (contact_overlap_limit; the first of equal ones) into `bad` (0 if
   !> none) and that tolerance into `limit`; `over` the one with the
   !> largest overlap past `ovtol` but within its own tolerance (0 if none).
   !> Runs only when some contact is beyond ovtol, so it may look at every
   !> contact; the tolerances are computed for those beyond ovtol alone.
   subroutine overlap_judge(geo, void, gap_new, ovtol, user, bad, limit, over)
      type(geometry_t), intent(in) :: geo
      logical(l1), intent(in) :: void(:)
      real(wp), intent(in) :: gap_new(:), ovtol
      logical, intent(in) :: user
      integer(ip), intent(out) :: bad, over
      real(wp), intent(out) :: limit
      integer(ip) :: c
      real(wp) :: worst, lc, most
      bad = 0
      over = 0
      limit = ovtol
      worst = ovtol
      most = ovtol
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c) .or. void(c)) cycle
         if (.not. -gap_new(c) > ovtol) cycle
         lc = contact_overlap_limit(geo, c, ovtol, user)
         if (-gap_new(c) > lc) then
            if (-gap_new(c) > worst) then
               worst = -gap_new(c)
               bad = c
               limit = lc
            end if
         else if (-gap_new(c) > most) then
            most = -gap_new(c)
            over = c
         end if
      end do
   end subroutine overlap_judge

   !> The overlap contact `c` may reach before "Contact Overlap Too Great"
   !> (UDEC manual (ICG1.5, 1989), Section 5.3: OVTOL, by default one-half
   !> the rounding length d). `ovtol` is the model's OVTOL; `user`: given by
   !> SET OVTOL, the user's limit for every contact.
   !> By default the tolerance is the contact's own, from the geometry of
   !> its rounded corners (manual Section 3.3, Fig. 3-3d).
   !> - The normal of two corners in contact is the line of their circle
   !>   centres; overlapping by o, the centres are r1 + r2 - o apart, and a
   !>   shear u turns the normal by u / (r1 + r2 - o): at o = r1 + r2 the
   !>   normal is lost. A normal force Fn turning so is a spring of
   !>   stiffness Fn / (r1 + r2 - o) across the normal; with Fn = kn o (kn
   !>   the contact's normal stiffness, for which the time step is set) it
   !>   passes kn at o = (r1 + r2) / 2: the tolerance, half the sum.
   !> - A corner (radius rc) against an edge has the edge's normal whatever
   !>   the overlap (no turning); it turns into a corner-corner contact with
   !>   the edge's end corner (radius rf) when it slides past the straight
   !>   part, and the gaps agree at that switch while the corner's centre is
   !>   less than rf behind the edge's line, overlap < rc + rf (beyond, the
   !>   gap and the normal jump): the end corner nearer the contact counts,
   !>   and the tolerance is switch_fraction (0.9) of rc + rf. A contact that
   !>   switches is judged at once as corner-corner (half the sum), so an
   !>   overlap past that half stops the run at the switch, its gap whole.
   !>   (Until session 42 half the sum for either kind: new users' tunnels
   !>   with soft joints stopped on wall contacts of this kind at 0.7 of
   !>   rc + rf, the statics sound; docs/robustness.md, round 3.)
   !> Two more bounds: twice the rounding length d, the width of a corner's
   !> rounded zone (its arc runs from d before the vertex to d after it), so
   !> that blunt corners, whose
   !> radii grow without bound as they flatten, stay within the scale the
   !> user set with ROUND (the manual's remedy for overlaps, Section 5.3);
   !> and a quarter of the shortest edge at the contact's corners and of its
   !> facing edge (EDGE keeps edges >= 2 d, whose quarter is the manual's
   !> d / 2): a sliver's contact never gets a tolerance of its own size.
   !> Never below ovtol. Two right-angled corners: d = 2 OVTOL (corner-edge:
   !> 1.8 d); a 50 degree wedge tip (radius 0.47 d) against the edge of a
   !> 130 degree corner's block (2.1 d): 2 d (0.9 x 2.6 d, capped); two 30
   !> degree tips (radii 0.27 d): OVTOL. A
   !> corner of radius 0 (a straight vertex: a zoned block's gridpoint, the
   !> end of a joint on the side of another; or a re-entrant corner) is not
   !> rounded: its contact meets the facing edge anywhere between the edge's
   !> vertices and never turns on an arc (contact_geometry), so it puts no
   !> radius bound on the tolerance: it counts as 2 d.
   pure real(wp) function contact_overlap_limit(geo, c, ovtol, user) result(limit)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: ovtol
      logical, intent(in) :: user
      integer :: which
      real(wp) :: measure
      call contact_overlap_bound(geo, c, ovtol, user, limit, which, measure)
   end function contact_overlap_limit

   !> contact_overlap_limit's `limit` and the bound that set it, for the
   !> stop's message: `which` one of the overlap_bound_* codes (OVTOL: SET
   !> OVTOL's, or the floor; radii: half their sum r1 + r2, the overlap at
   !> which the corners' circle centres meet, in `measure`; switch: a
   !> corner-edge contact's switch_fraction of rc + rf, in `measure`; round: 2 d;
   !> edge: a quarter of the shortest edge at the contact, its length in
   !> `measure`). `measure` 0 for OVTOL and round.
   pure subroutine contact_overlap_bound(geo, c, ovtol, user, limit, which, measure)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: ovtol
      logical, intent(in) :: user
      real(wp), intent(out) :: limit, measure
      integer, intent(out) :: which
      integer(ip) :: a, e, f
      real(wp) :: r, lmin, frac
      logical :: edge_contact
      limit = ovtol
      which = overlap_bound_ovtol
      measure = 0.0_wp
      if (user) return
      associate (ct => geo%contacts, co => geo%corners)
         select case (ct%kind(c))
         case (1)
            a = ct%end1(c)
            f = ct%end2(c)
            r = radius_of(a) + radius_of(f)
            lmin = min(corner_edges_min(a), corner_edges_min(f))
            frac = 0.5_wp
            edge_contact = .false.
         case default
            if (ct%kind(c) == 2) then
               a = ct%end1(c)
               e = ct%end2(c)
            else
               a = ct%end2(c)
               e = ct%end1(c)
            end if
            ! the end of edge e nearer the corner's centre
            f = co%next(e)
            if (length2(co%rx(a) - co%x(e), co%ry(a) - co%y(e)) < &
                length2(co%rx(a) - co%x(f), co%ry(a) - co%y(f))) f = e
            r = radius_of(a) + radius_of(f)
            lmin = min(corner_edges_min(a), length2(co%x(co%next(e)) - co%x(e), &
                                                    co%y(co%next(e)) - co%y(e)))
            frac = switch_fraction
            edge_contact = .true.
         end select
      end associate
      limit = max(ovtol, min(frac*r, 2.0_wp*geo%round, 0.25_wp*lmin))
      if (limit > ovtol) then
         if (limit == frac*r) then
            which = merge(overlap_bound_switch, overlap_bound_radii, edge_contact)
            measure = r
         else if (limit == 2.0_wp*geo%round) then
            which = overlap_bound_round
         else
            which = overlap_bound_edge
            measure = lmin
         end if
      end if
   contains
      !> corner k's rounding radius; 2 d for a corner of radius 0
      pure real(wp) function radius_of(k) result(rk)
         integer(ip), intent(in) :: k
         rk = geo%corners%radius(k)
         if (.not. rk > 0.0_wp) rk = 2.0_wp*geo%round
      end function radius_of
      !> the shorter of corner k's two edges
      pure real(wp) function corner_edges_min(k) result(l)
         integer(ip), intent(in) :: k
         associate (co => geo%corners)
            l = min(length2(co%x(co%next(k)) - co%x(k), co%y(co%next(k)) - co%y(k)), &
                    length2(co%x(k) - co%x(co%prev(k)), co%y(k) - co%y(co%prev(k))))
         end associate
      end function corner_edges_min
   end subroutine contact_overlap_bound

   !> contact_geometry_all over contacts c0..c1: `bad` the first contact with
   !> the largest overlap `worst` beyond ovtol (bad 0, worst ovtol if none).
   subroutine contact_geometry_range(geo, c0, c1, tol, frame, void, ovtol, gap_new, bad, worst)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: c0, c1
      real(wp), intent(in) :: tol, ovtol
      real(wp), intent(in) :: frame(4, *)
      logical(l1), intent(in) :: void(:)
      real(wp), intent(inout) :: gap_new(:)
      integer(ip), intent(out) :: bad
      real(wp), intent(out) :: worst
      integer(ip) :: c
      real(wp) :: gap, nx, ny, px, py
      bad = 0
      worst = ovtol
      c = c0
      do
         associate (ct => geo%contacts, cr => geo%corners)
            call geometry_fast_kernel(c, c1, ct%live, ct%kind, ct%end1, ct%end2, &
                                      ct%nx, ct%ny, ct%x, ct%y, ct%gap, cr%x, cr%y, &
                                      cr%rx, cr%ry, cr%radius, cr%prev, tol, frame, void, gap_new, &
                                      worst, bad)
         end associate
         if (c > c1) exit
         ! contact c is not one of the written-out cases
         call contact_geometry(geo, c, tol, gap, nx, ny, px, py, frame)
         associate (ct => geo%contacts)
            call keep_geometry(c, gap, nx, ny, px, py, void, gap_new, ct%nx, ct%ny, ct%x, ct%y, &
                               ct%gap, worst, bad)
         end associate
         c = c + 1
      end do
   end subroutine contact_geometry_range

   !> The loop of contact_geometry_all from contact `c` on: returns in `c` the
   !> first live contact that is not a written-out case (n + 1 if none).
   subroutine geometry_fast_kernel(c, n, live, kind, end1, end2, cnx, cny, &
                                   cx, cy, cgap, x, y, rx, ry, radius, prev, tol, frame, void, &
                                   gap_new, worst, bad)
      integer(ip), intent(inout) :: c
      integer(ip), intent(in) :: n
      logical(l1), intent(in) :: live(*)
      integer(i1), intent(in) :: kind(*)
      integer(ip), intent(in) :: end1(*), end2(*), prev(*)
      real(wp), intent(inout) :: cnx(*), cny(*), cx(*), cy(*), cgap(*)
      real(wp), intent(in) :: x(*), y(*), rx(*), ry(*), radius(*)
      real(wp), intent(in) :: tol
      real(wp), intent(in) :: frame(4, *)
      logical(l1), intent(in) :: void(*)
      real(wp), intent(inout) :: gap_new(*), worst
      integer(ip), intent(inout) :: bad
      integer(ip) :: cc, e, d
      real(wp) :: gap, nx, ny, px, py, ux, uy, ex, ey, s, wx, wy, dist, ta
      logical :: done
      ta = 1.0e-9_wp      ! as contact_geometry
      do while (c <= n)
         if (.not. live(c)) then
            c = c + 1
            cycle
         end if
         done = .false.
         select case (kind(c))
         case (2, 3)
            if (kind(c) == 2) then
               cc = end1(c); e = end2(c)
            else
               cc = end2(c); e = end1(c)
            end if
            ux = frame(1, e)
            uy = frame(2, e)
            ex = -uy
            ey = ux
            s = (rx(cc) - x(e))*ux + (ry(cc) - y(e))*uy
            if (.not. (s < frame(3, e) - tol .or. s > frame(4, e) + tol)) then
               gap = (rx(cc) - x(e))*ex + (ry(cc) - y(e))*ey - radius(cc)
               px = rx(cc) - ex*(radius(cc) + 0.5_wp*gap)
               py = ry(cc) - ey*(radius(cc) + 0.5_wp*gap)
               if (kind(c) == 2) then
                  nx = -ex; ny = -ey
               else
                  nx = ex; ny = ey
               end if
               done = .true.
            end if
         case default
            cc = end1(c)
            d = end2(c)
            wx = rx(d) - rx(cc)
            wy = ry(d) - ry(cc)
            call unit_vector(wx, wy, dist, 0.0_wp, 0.0_wp)
            if (dist > 0.0_wp) then
               ! cone_side(d, -w) == 0 and cone_side(cc, w) == 0
               done = in_corner_arc(frame, prev(d), d, -wx, -wy, ta)
               if (done) done = in_corner_arc(frame, prev(cc), cc, wx, wy, ta)
               if (done) then
                  gap = dist - radius(cc) - radius(d)
                  nx = wx; ny = wy
                  px = rx(cc) + wx*(radius(cc) + 0.5_wp*gap)
                  py = ry(cc) + wy*(radius(cc) + 0.5_wp*gap)
               end if
            end if
         end select
         if (.not. done) return
         call keep_geometry(c, gap, nx, ny, px, py, void, gap_new, cnx, cny, cx, cy, cgap, worst, bad)
         c = c + 1
      end do
   end subroutine geometry_fast_kernel

   !> The geometry found for contact c, kept (geometry_fast_kernel and
   !> contact_geometry_range): the gap in gap_new(c) (the one of the force
   !> pass), the normal and the point in the contact's arrays; a void
   !> contact's gap is its gap now, another's overlap beyond `worst` makes it
   !> the `bad` one.
   pure subroutine keep_geometry(c, gap, nx, ny, px, py, void, gap_new, cnx, cny, cx, cy, cgap, &
                                 worst, bad)
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: gap, nx, ny, px, py
      logical(l1), intent(in) :: void(*)
      real(wp), intent(inout) :: gap_new(*), cnx(*), cny(*), cx(*), cy(*), cgap(*), worst
      integer(ip), intent(inout) :: bad
      gap_new(c) = gap
      cnx(c) = nx
      cny(c) = ny
      cx(c) = px
      cy(c) = py
      if (void(c)) then
         cgap(c) = gap
      else if (-gap > worst) then
         worst = -gap
         bad = c
      end if
   end subroutine keep_geometry

   !> The direction (vx, vy) is within the arc of corner d, whose edges are
   !> p = prev(d) and d (frames of edge_frames_compute): cone_side(d, v) == 0
   !> with cone_side's expressions, for geometry_fast_kernel.
   pure logical function in_corner_arc(frame, p, d, vx, vy, ta) result(inside)
      real(wp), intent(in) :: frame(4, *)
      integer(ip), intent(in) :: p, d
      real(wp), intent(in) :: vx, vy, ta
      real(wp) :: ax, ay, bx, by, ci, co
      ax = -frame(2, p); ay = frame(1, p)
      bx = -frame(2, d); by = frame(1, d)
      ci = ax*vy - ay*vx
      co = vx*by - vy*bx
      inside = .not. (ci > ta) .and. .not. (co > ta) .and. &
               .not. (ax*vx + ay*vy < 0.0_wp .and. bx*vx + by*vy < 0.0_wp)
   end function in_corner_arc

   !> Nearest feature of block `b`'s rounded boundary to the circle of
   !> corner `cc` (of another block): `fkind` 1 corner / 2 edge, `fid` its
   !> corner id (an edge is named by its first corner), `gap` the signed gap
   !> (negative when overlapping, judged from the feature's outward side).
   !>
   !> An edge with the corner's centre behind its line counts only when the
   !> centre is inside block b's polygon (crossing number over the ring). A
   !> thin block (a sliver between a TUNNEL wall and a joint, 1 cm across)
   !> has the centre of a corner that lies OUTSIDE it, beside one edge but
   !> not facing it, within the margin behind its far edge: that edge is not
   !> a feature the corner can touch, and a contact made with it starts as
   !> an overlap of the sliver's width (found on a 40 m tunnel model: a
   !> corner 1.7 cm beside a needle block was given a contact with the
   !> needle's far edge, overlap 3.3 cm, and the run stopped with Contact
   !> Overlap Too Great).
   pure subroutine corner_nearest_feature(geo, cc, b, fkind, fid, gap)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: cc, b
      integer, intent(out) :: fkind
      integer(ip), intent(out) :: fid
      real(wp), intent(out) :: gap
      integer(ip) :: k, e, f
      real(wp) :: cx, cy, rc, ux, uy, ex, ey, s0, s1, s, dist, best, g, dx, dy
      real(wp), parameter :: ta = 1.0e-6_wp
      logical :: facing, inside
      cx = geo%corners%rx(cc)
      cy = geo%corners%ry(cc)
      rc = geo%corners%radius(cc)
      best = huge(1.0_wp)
      fkind = 0
      fid = 0
      gap = huge(1.0_wp)
      ! is the centre inside b's polygon (crossing number)
      inside = block_contains_point(geo, b, cx, cy)
      e = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         ! the arc of corner e: only where the line of centres leaves both
         ! rounded corners through their arcs (a blunt corner's circle is
         ! large and reaches across its block; its far side is not boundary)
         dx = cx - geo%corners%rx(e)
         dy = cy - geo%corners%ry(e)
         dist = length2(dx, dy)
         g = dist - rc - geo%corners%radius(e)
         facing = .true.
         if (dist > 0.0_wp) then
            ! unit direction: cone_side's allowance is for unit vectors
            if (geo%corners%radius(e) > 0.0_wp) &
               facing = cone_side(geo, e, dx/dist, dy/dist, ta) == 0
            if (rc > 0.0_wp .and. facing) facing = cone_side(geo, cc, -dx/dist, -dy/dist, ta) == 0
         end if
         if (facing .and. abs(dist - geo%corners%radius(e)) < best) then
            best = abs(dist - geo%corners%radius(e))
            fkind = 1
            fid = e
            gap = g
         end if
         ! the straight part of edge e
         call edge_frame(geo, e, ux, uy, ex, ey, s0, s1)
         s = (cx - geo%corners%x(e))*ux + (cy - geo%corners%y(e))*uy
         facing = s >= s0 .and. s <= s1 .and. s1 > s0
         ! a rounded corner meets an edge with its arc: the edge's inward
         ! normal must point out of the corner's cone -- within
         ! reflex_min_turn: one of the corner's own edges then lies along
         ! this edge (an edge-edge contact, Fig 3-3b) and the corner is the
         ! end of the shared stretch, whichever way a turn of a few
         ! microradians tips it. Found on the new user's tunnel (seed 7):
         ! two opposite wedges of a joint crossing slid past each other's
         ! tips along their common joint; the tip whose edge normal lay
         ! 1e-6 outside the other's arc got no contact, and the other tip
         ! took the whole thrust on the minimum contact length until
         ! Contact Overlap Too Great at cycle 22518.
         if (facing .and. rc > 0.0_wp) facing = cone_side(geo, cc, -ex, -ey, reflex_min_turn) == 0
         if (facing) then
            g = (cx - geo%corners%x(e))*ex + (cy - geo%corners%y(e))*ey
            ! behind the edge's line but outside the block: the far side
            ! of a thin block, not a feature the corner touches
            if (g < 0.0_wp .and. .not. inside) facing = .false.
         end if
         if (facing) then
            if (abs(g) < best) then
               best = abs(g)
               fkind = 2
               fid = e
               gap = g - rc
            end if
         end if
         e = geo%corners%next(e)
      end do
   end subroutine corner_nearest_feature

   !> |(x, y)|, the same value as the C library's `hypot` gives (GNU libc 2.35
   !> and later, x86-64): sqrt(ax**2 + ay**2) corrected by one Newton-like
   !> step from the rounding error of the squares (ax >= ay; the correction
   !> of C. F. Borges, "An Improved Algorithm for hypot(a,b)", 2019,
   !> written without a fused multiply-add) in the library's common range,
   !> the library's hypot outside it. Written here so that the compiler
   !> inlines it into the contact loops: a library call cost about 58
   !> instructions, a tenth of a rigid step (docs/performance.md). Compared
   !> with `hypot` on 300 million random pairs over the whole exponent range:
   !> no difference (unit.test_contact_length checks 6.8 million, from a
   !> fixed seed). A shorter side below the library's threshold 2**-459 is
   !> scaled by the library; taking 2**-511 there instead was one ulp off on
   !> one pair in 300 million, which a random seed found in CI.
   elemental real(wp) function length2(x, y) result(h)
      real(wp), intent(in) :: x, y
      real(wp) :: ax, ay
      ax = abs(x)
      ay = abs(y)
      if (ay > ax) then
         ax = abs(y)
         ay = abs(x)
      end if
      ! the common range written out (small enough to be inlined): a side
      ! negligible beside the other (an edge along an axis) or both in range;
      ! the rest (arguments the library scales, infinities and NaN: every
      ! comparison false) by the library itself
      if (ax <= length2_large .and. ax >= length2_small) then
         if (.not. (ay > ax*length2_eps)) then
            h = ax + ay
         else if (ay >= length2_tiny) then
            h = corrected_root(ax, ay)
         else
            h = hypot(x, y)
         end if
      else
         h = hypot(x, y)
      end if
   end function length2

   !> The core of length2 for ax >= ay > 0 in range.
   elemental real(wp) function corrected_root(ax, ay) result(h)
      real(wp), intent(in) :: ax, ay
      real(wp) :: d, t1, t2
      h = sqrt(ax*ax + ay*ay)
      if (h <= 2.0_wp*ay) then
         d = h - ay
         t1 = ax*(2.0_wp*d - ax)
         t2 = (d - 2.0_wp*(ax - ay))*d
      else
         d = h - ax
         t1 = 2.0_wp*d*(ax - 2.0_wp*ay)
         t2 = (4.0_wp*d - ay)*ay + d*d
      end if
      h = h - (t1 + t2)/(2.0_wp*h)
   end function corrected_root

end module contact_kinematics
