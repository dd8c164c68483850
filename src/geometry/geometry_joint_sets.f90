!> Generated crack patterns: JREGION, JSET (manual Fig 4-1), TUNNEL, ARC.
!> All of them lay down CRACK segments (geometry_cutting), so partial joints,
!> the JREGION limit and the tunnel periphery behave as for CRACK.
module geometry_joint_sets
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use core_output, only: output_t
   use geometry_polygon, only: point_in_polygon, &
                               polygon_boundary_distance, polygon_clip_convex_area, &
                               segment_distance, require_clockwise_simple, polygon_signed_area
   use core_constants, only: pi
   use model_geometry, only: geometry_t, geometry_random, geometry_add_tunnel, &
                             geometry_block_polygon, geometry_refused_cuts
   use geometry_cutting, only: cut_crack, cut_segment_pieces, ring_polygon, ring_key_cuts, &
                               cut_key_pending_loops, cut_key_wrapping_blocks
   implicit none
   private
   public :: joint_region, joint_set, joint_tunnel, joint_arc, ring_snap_reach

   !> How far a TUNNEL's opening departs from the ring polygon drawn: the
   !> blocks DELETE ANN of the ring would keep hold rock inside the polygon,
   !> or those it would take (centroid inside) rock outside it.
   type, public :: ring_fit_t
      !> blocks whose part on the wrong side exceeds `allow` (the first three
      !> named, the largest first), and their parts there (m2)
      integer(ip) :: n = 0
      integer(ip) :: block(3) = 0
      real(wp) :: wrong(3) = 0.0_wp
      !> whether DELETE ANN of the ring takes the block (centroid inside)
      logical :: taken(3) = .false.
      !> the wrong parts of all blocks, the polygon's area, the allowance
      real(wp) :: total = 0.0_wp, ring_area = 0.0_wp, allow = 0.0_wp
      !> the ring's side, and whether 2 ROUND exceeds the ring's own reach
      real(wp) :: side = 0.0_wp
      logical :: coarse = .false.
   end type ring_fit_t

contains

   !> JREGION x1 y1 ... x4 y4: clockwise quadrilateral limiting JSET and
   !> CRACK JREG.
   subroutine joint_region(geo, x, y, error)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x(4), y(4)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tol
      tol = 1.0e-9_wp*max(maxval(x) - minval(x), maxval(y) - minval(y))
      call require_clockwise_simple(x, y, tol, 'JREGION', 'the quadrilateral intersects itself', &
                                    error)
      if (allocated(error)) return
      geo%jregion_x = x
      geo%jregion_y = y
      geo%has_jregion = .true.
   end subroutine joint_region

   !> JSET a(m),a(d) t(m),t(d) g(m),g(d) s(m),s(d) <x0 y0> <ad0>.
   !> Tracks at angle a (degrees, drawn per track) are spaced s apart
   !> normal to the mean direction; along each track, joints of trace t
   !> alternate with gaps g (both drawn per joint); each joint is turned by
   !> ad0 degrees from its track. Draws are uniform in [mean-dev, mean+dev]
   !> from the model's seeded generator. A joint starts at (x0, y0) (default:
   !> the lower-left corner of the region's box); the pattern fills the
   !> JREGION, or the whole model when no JREGION was given.
   subroutine joint_set(geo, angle, trace, gap, spacing, error, out, origin, ad0)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: angle(2), trace(2), gap(2), spacing(2)
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      real(wp), intent(in), optional :: origin(2), ad0
      real(wp) :: rx(4), ry(4), x0, y0, a, ux, uy, vx, vy, off, step, pmin, pmax
      real(wp) :: ta, tux, tuy, qmin, qmax, q, t, g, bx, by, dj, period
      real(wp) :: live_box(4)
      integer(ip) :: dir, ntrack
      if (.not. geo%block_created) then
         call set_error(error, 'JSET: no BLOCK has been created')
         return
      end if
      if (.not. spacing(1) - abs(spacing(2)) > 0.0_wp) then
         call set_error(error, 'JSET: spacing mean must exceed its deviation')
         return
      end if
      if (.not. trace(1) + abs(trace(2)) > 0.0_wp) then
         call set_error(error, 'JSET: trace length must be positive')
         return
      end if
      if (gap(1) - abs(gap(2)) < 0.0_wp) then
         call set_error(error, 'JSET: gap mean must not be below its deviation')
         return
      end if
      if (.not. geo%has_jregion .and. .not. any(geo%blocks%live(1:geo%blocks%n))) then
         call set_error(error, 'JSET: every block has been deleted; there is nothing to cut')
         return
      end if
      call live_blocks_box(geo, live_box)
      call region_box(geo, rx, ry)
      x0 = minval(rx)
      y0 = minval(ry)
      if (present(origin)) then
         x0 = origin(1)
         y0 = origin(2)
      end if
      ! an origin so far away that a spacing is lost to round-off there
      ! cannot place the joints: refuse it instead of looping for ever
      if (hypot(x0 - 0.5_wp*(minval(rx) + maxval(rx)), y0 - 0.5_wp*(minval(ry) + maxval(ry))) > &
          1.0e9_wp*max(maxval(rx) - minval(rx), maxval(ry) - minval(ry))) then
         call set_error(error, 'JSET: the origin (x0, y0) is more than 1e9 model sizes '// &
                        'from the region to cut; give an origin near the model')
         return
      end if
      dj = 0.0_wp
      if (present(ad0)) dj = ad0*pi/180.0_wp
      a = angle(1)*pi/180.0_wp
      ux = cos(a)
      uy = sin(a)
      vx = -uy
      vy = ux
      ! offsets of tracks along the normal needed to cover the region
      pmin = minval(vx*(rx - x0) + vy*(ry - y0))
      pmax = maxval(vx*(rx - x0) + vy*(ry - y0))
      ntrack = 0
      do dir = 1, -1, -2
         off = 0.0_wp
         ! an origin far outside the region: start at the last whole mean
         ! spacing before the region instead of walking there track by track
         if (dir > 0 .and. pmin > 0.0_wp) off = spacing(1)*aint(pmin/spacing(1))
         if (dir < 0 .and. pmax < 0.0_wp) off = spacing(1)*aint(pmax/spacing(1))
         if (dir < 0) off = off - draw(spacing)
         do
            if (dir > 0 .and. off > pmax) exit
            if (dir < 0 .and. off < pmin) exit
            ! Ctrl-C / SIGTERM: the caller puts the blocks back as they were
            if (interrupt_pending()) then
               call set_error(error, 'JSET interrupted: the blocks are left as before it')
               return
            end if
            ntrack = ntrack + 1
            call lay_track(off)
            step = draw(spacing)
            off = off + real(dir, wp)*step
         end do
      end do
   contains
      real(wp) function draw(pair)
         real(wp), intent(in) :: pair(2)
         draw = pair(1) + pair(2)*(2.0_wp*geometry_random(geo) - 1.0_wp)
      end function draw
      subroutine lay_track(o)
         real(wp), intent(in) :: o
         integer(ip) :: sgn
         ta = draw(angle)*pi/180.0_wp
         tux = cos(ta)
         tuy = sin(ta)
         bx = x0 + o*vx
         by = y0 + o*vy
         qmin = minval(tux*(rx - bx) + tuy*(ry - by))
         qmax = maxval(tux*(rx - bx) + tuy*(ry - by))
         ! forward from the base point, then backward
         period = max(trace(1), 0.0_wp) + gap(1)
         do sgn = 1, -1, -2
            q = 0.0_wp
            ! the same for a base point far along the track
            if (period > 0.0_wp) then
               if (sgn > 0 .and. qmin > 0.0_wp) q = period*aint(qmin/period)
               if (sgn < 0 .and. qmax < 0.0_wp) q = period*aint(qmax/period)
            end if
            if (sgn < 0) q = q - draw(gap)
            do
               if (sgn > 0 .and. q > qmax) exit
               if (sgn < 0 .and. q < qmin) exit
               if (interrupt_pending()) return
               t = draw(trace)
               g = draw(gap)
               if (t > 0.0_wp) then
                  if (sgn > 0) then
                     call lay_joint(bx + q*tux, by + q*tuy, t)
                  else
                     call lay_joint(bx + (q - t)*tux, by + (q - t)*tuy, t)
                  end if
               end if
               q = q + real(sgn, wp)*(max(t, 0.0_wp) + g)
               if (max(t, 0.0_wp) + g <= 0.0_wp) exit
            end do
         end do
      end subroutine lay_track
      subroutine lay_joint(sx, sy, len)
         real(wp), intent(in) :: sx, sy, len
         type(error_t), allocatable :: err
         real(wp) :: ex, ey
         ex = sx + len*cos(ta + dj)
         ey = sy + len*sin(ta + dj)
         ! a joint clear of every block cuts and records nothing: skip the
         ! search (a JREGION much larger than the model draws many of them)
         if (max(sx, ex) < live_box(1) .or. min(sx, ex) > live_box(2) .or. &
             max(sy, ey) < live_box(3) .or. min(sy, ey) > live_box(4)) return
         call cut_crack(geo, sx, sy, ex, ey, geo%has_jregion, err, out, jplot=.true.)
      end subroutine lay_joint
   end subroutine joint_set

   !> Box (xmin, xmax, ymin, ymax) of the live blocks, widened by the
   !> geometry tolerance; empty (xmin > xmax) when no block is live.
   subroutine live_blocks_box(geo, box)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(out) :: box(4)
      integer(ip) :: n
      n = geo%blocks%n
      box = [1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp]
      if (.not. any(geo%blocks%live(1:n))) return
      box(1) = minval(geo%blocks%xmin(1:n), mask=geo%blocks%live(1:n)) - 2.0_wp*geo%tol
      box(2) = maxval(geo%blocks%xmax(1:n), mask=geo%blocks%live(1:n)) + 2.0_wp*geo%tol
      box(3) = minval(geo%blocks%ymin(1:n), mask=geo%blocks%live(1:n)) - 2.0_wp*geo%tol
      box(4) = maxval(geo%blocks%ymax(1:n), mask=geo%blocks%live(1:n)) + 2.0_wp*geo%tol
   end subroutine live_blocks_box

   !> Box of the JREGION or of all live blocks.
   subroutine region_box(geo, rx, ry)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(out) :: rx(4), ry(4)
      real(wp) :: x0, x1, y0, y1, m
      integer(ip) :: n
      if (geo%has_jregion) then
         rx = geo%jregion_x
         ry = geo%jregion_y
         return
      end if
      n = geo%blocks%n
      x0 = minval(geo%blocks%xmin(1:n), mask=geo%blocks%live(1:n))
      x1 = maxval(geo%blocks%xmax(1:n), mask=geo%blocks%live(1:n))
      y0 = minval(geo%blocks%ymin(1:n), mask=geo%blocks%live(1:n))
      y1 = maxval(geo%blocks%ymax(1:n), mask=geo%blocks%live(1:n))
      ! a small margin so joints reach right through the boundary
      m = 1.0e-3_wp*max(x1 - x0, y1 - y0)
      rx = [x0 - m, x0 - m, x1 + m, x1 + m]
      ry = [y0 - m, y1 + m, y1 + m, y0 - m]
   end subroutine region_box

   !> TUNNEL xc yc r n: a ring of n crack segments; later cracks stop at its
   !> periphery. Only the last TUNNEL limits cracks, so a TUNNEL of radius 0
   !> lifts the limit (the manual's advice); the ring itself may be stopped by
   !> the previous tunnel.
   !>
   !> A block cannot have a hole, so a ring lying wholly inside one block
   !> (the first block, or rock no joint crosses there) cannot split it. The
   !> manual notes that such commands are not accepted on a single block;
   !> here the block is cut by two horizontal cracks, from the ring's
   !> rightmost corner and from a leftmost corner out to the block's
   !> boundary, which lets the ring separate the opening (with a note).
   !> `straddling` (optional) returns how many blocks the finished ring still
   !> crosses: 0 when the opening is made of whole blocks; `which` (optional)
   !> the first of them (as many as it holds, 0 past the count); `fit`
   !> (optional) how far the opening departs from the ring drawn (ring_fit;
   !> blocks wrong by more than the side x the snap reach, at most 0.1 r,
   !> named).
   subroutine joint_tunnel(geo, xc, yc, r, n, error, out, straddling, which, fit)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: xc, yc, r
      integer(ip), intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      integer(ip), intent(out), optional :: straddling
      integer(ip), intent(out), optional :: which(:)
      type(ring_fit_t), intent(out), optional :: fit
      integer(ip) :: b, nstraddle, ncorner0
      real(wp), allocatable :: tx(:), ty(:), sx(:), sy(:)
      real(wp) :: side
      if (present(straddling)) straddling = 0
      if (present(which)) which = 0
      if (.not. geo%block_created) then
         call set_error(error, 'TUNNEL: no BLOCK has been created')
         return
      end if
      if (r < 0.0_wp .or. (r > 0.0_wp .and. n < 3)) then
         call set_error(error, 'TUNNEL: need r >= 0 and at least 3 segments')
         return
      end if
      ! corners made from here on belong to blocks this TUNNEL cut
      ncorner0 = geo%corners%n
      if (r > 0.0_wp) then
         call ring_polygon(xc, yc, r, n, tx, ty)
         b = enclosing_block(geo, tx, ty)
         ! a ring corner nearly on an existing joint or edge is moved onto it
         ! (cut_snapped_ring)
         call cut_snapped_ring(geo, tx, ty, .true., n, sx, sy, error, out, &
                               small=[geo%edge_min*hypot(tx(2) - tx(1), ty(2) - ty(1)), xc, yc, r, &
                                      real(n, wp)])
         if (allocated(error)) return
      end if
      call geometry_add_tunnel(geo, xc, yc, r, max(n, 3_ip))
      if (r > 0.0_wp) then
         if (b > 0) then
            ! cracks are now clipped to the outside of this ring
            ! from the ring's rightmost corner (angle 0) and a leftmost one
            call ring_key_cuts(geo, b, 'TUNNEL', tx(1), ty(1), tx(n/2 + 1), ty(n/2 + 1), r, &
                               error, out)
            if (allocated(error)) return
         end if
         call cut_key_wrapping_blocks(geo, sx, sy, 'TUNNEL', error, out)
         if (allocated(error)) return
         nstraddle = ring_straddling(geo, sx, sy, ncorner0, which)
         if (present(straddling)) straddling = nstraddle
         if (present(fit)) then
            ! a corner snapped or a side bent by the reach moves the wall by
            ! at most a triangle of the side and that reach; a reach beyond
            ! a tenth of the radius (2 ROUND against a small ring) is not
            ! allowed for: the opening no longer follows the ring
            side = hypot(tx(2) - tx(1), ty(2) - ty(1))
            call ring_fit(geo, tx, ty, side*min(ring_snap_reach(geo, side, n), 0.1_wp*r), fit)
            fit%side = side
            fit%coarse = ring_turn_reach(side, n) < ring_snap_reach(geo, side, n)
         end if
      end if
   end subroutine joint_tunnel

   !> Cut the ring or arc of corners (tx, ty) as cracks from corner to
   !> corner (`closed`: back to the first), its corners nearly on an existing
   !> joint or edge moved onto it first (snap_to_edges, bend_to_tips;
   !> `nring`: the sides of the whole ring). Where that makes cuts be
   !> refused, the line is also cut as drawn, and the one of the two that
   !> refuses fewer cuts is kept (the snapped one on a tie): a refused cut
   !> leaves a crack-like notch in the opening's wall. Only the kept one's
   !> notes are printed. (sx, sy): the corners cut. `small`: TUNNEL's ring
   !> [area, xc, yc, r, n], a piece outside the ring below EDGE x the side (a
   !> block's tip the ring cuts off, a thousandth of its neighbours) joins a
   !> neighbour where it can.
   !>
   !> A TUNNEL ring whose snap reach is 2 ROUND, more than its own (side x
   !> sin(theta), ring_turn_reach), is cut three ways: snapped with each
   !> reach and as drawn; the one refusing fewest cuts is kept, on a tie the
   !> one whose ring crosses fewest blocks (ring_straddling), then the
   !> first (2 ROUND: a corner nearer a joint leaves a sliver). Seed 1 of
   !> tools/ring_straddle_sweep.py, draw 6 (a joint at 2.6 degrees to a
   !> side of a 46-gon, ROUND 0.02, reach 0.04 m) crossed a block with the
   !> 2 ROUND reach and none with the ring's own. Choosing by the area off
   !> the ring instead (ring_fit) took the ring's own reach where a joint
   !> grazes it (e2e.tunnel_grazing): the sliver came back.
   subroutine cut_snapped_ring(geo, tx, ty, closed, nring, sx, sy, error, out, small)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: tx(:), ty(:)
      logical, intent(in) :: closed
      integer(ip), intent(in) :: nring
      real(wp), allocatable, intent(out) :: sx(:), sy(:)
      type(error_t), allocatable, intent(inout) :: error
      type(output_t), intent(in), optional :: out
      real(wp), intent(in), optional :: small(5)
      type(geometry_t), allocatable :: saved, kept
      real(wp), allocatable :: cx(:), cy(:)
      real(wp) :: side, reach(3)
      integer(ip) :: nreach, k, nref0, nref, best_ref, nstr, best_str
      logical :: by_straddle
      side = hypot(tx(2) - tx(1), ty(2) - ty(1))
      ! the reaches to try, the full one first; 0: the ring as drawn
      reach(1) = ring_snap_reach(geo, side, nring)
      nreach = 2
      by_straddle = .false.
      if (present(small) .and. closed) by_straddle = ring_turn_reach(side, nring) < reach(1)
      if (by_straddle) then
         reach(2) = ring_turn_reach(side, nring)
         nreach = 3
      end if
      reach(nreach) = 0.0_wp
      sx = tx
      sy = ty
      call snap_to_edges(geo, sx, sy, reach(1))
      call bend_to_tips(geo, sx, sy, closed, reach(1))
      if (.not. by_straddle .and. .not. moved(sx, sy)) then
         call cut_line(tx, ty, .true.)
         return
      end if
      saved = geo
      nref0 = geometry_refused_cuts(geo)
      best_ref = huge(1_ip)
      best_str = huge(1_ip)
      do k = 1, nreach
         if (k > 1) then
            cx = tx
            cy = ty
            if (reach(k) > 0.0_wp) then
               call snap_to_edges(saved, cx, cy, reach(k))
               call bend_to_tips(saved, cx, cy, closed, reach(k))
            end if
            ! the same corners as the last kept: nothing new to try
            if (size(cx) == size(sx)) then
               if (all(cx == sx) .and. all(cy == sy)) cycle
            end if
            ! without the fit, the line as drawn is tried only where the
            ! snapped one refused cuts
            if (.not. by_straddle .and. best_ref == 0) exit
            geo = saved
         else
            cx = sx
            cy = sy
         end if
         call cut_line(cx, cy, .false.)
         if (allocated(error)) return
         nref = geometry_refused_cuts(geo) - nref0
         nstr = 0
         if (by_straddle) nstr = ring_straddling(geo, cx, cy, saved%corners%n)
         if (nref < best_ref .or. (nref == best_ref .and. nstr < best_str)) then
            best_ref = nref
            best_str = nstr
            sx = cx
            sy = cy
            kept = geo
         end if
      end do
      geo = kept
      if (best_ref > 0 .and. present(out)) then
         ! again, for the notes of its refused cuts
         geo = saved
         call cut_line(sx, sy, .true.)
      end if
   contains
      !> Whether the corners (x, y) differ from those drawn.
      logical function moved(x, y)
         real(wp), intent(in) :: x(:), y(:)
         moved = size(x) /= size(tx)
         if (.not. moved) moved = any(x /= tx) .or. any(y /= ty)
      end function moved
      !> The cracks between consecutive corners (x, y); notes of refused
      !> cuts only when `notes` (a trial cut says nothing).
      subroutine cut_line(x, y, notes)
         real(wp), intent(in) :: x(:), y(:)
         logical, intent(in) :: notes
         integer(ip) :: j, n, nseg
         n = size(x, kind=ip)
         nseg = merge(n, n - 1_ip, closed)
         do j = 1, nseg
            if (notes) then
               call cut_crack(geo, x(j), y(j), x(modulo(j, n) + 1), y(modulo(j, n) + 1), &
                              .false., error, out, merge_below=small)
            else
               call cut_crack(geo, x(j), y(j), x(modulo(j, n) + 1), y(modulo(j, n) + 1), &
                              .false., error, merge_below=small)
            end if
            if (allocated(error)) return
         end do
      end subroutine cut_line
   end subroutine cut_snapped_ring

   !> How a TUNNEL's opening departs from the ring polygon (tx, ty) drawn
   !> (clockwise, convex): a block whose centroid lies inside it (DELETE ANN
   !> of the ring takes it) is wrong by its part outside the polygon, any
   !> other by its part inside; `fit` sums them and names the blocks wrong by
   !> more than `allow`, the largest first.
   subroutine ring_fit(geo, tx, ty, allow, fit)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: tx(:), ty(:), allow
      type(ring_fit_t), intent(out) :: fit
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: b, k, j
      real(wp) :: inside, wrong
      logical :: taken
      fit%ring_area = abs(polygon_signed_area(tx, ty))
      fit%allow = allow
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%xmax(b) < minval(tx) .or. geo%blocks%xmin(b) > maxval(tx)) cycle
         if (geo%blocks%ymax(b) < minval(ty) .or. geo%blocks%ymin(b) > maxval(ty)) cycle
         call geometry_block_polygon(geo, b, x, y)
         inside = polygon_clip_convex_area(x, y, tx, ty)
         taken = point_in_polygon(tx, ty, geo%blocks%xc(b), geo%blocks%yc(b))
         if (taken) then
            wrong = max(geo%blocks%area(b) - inside, 0.0_wp)
         else
            wrong = inside
         end if
         fit%total = fit%total + wrong
         if (.not. wrong > allow) cycle
         fit%n = fit%n + 1
         ! keep the three largest, in order
         do k = 1, size(fit%block)
            if (fit%block(k) == 0 .or. wrong > fit%wrong(k)) then
               do j = size(fit%block), k + 1, -1
                  fit%block(j) = fit%block(j - 1)
                  fit%wrong(j) = fit%wrong(j - 1)
                  fit%taken(j) = fit%taken(j - 1)
               end do
               fit%block(k) = b
               fit%wrong(k) = wrong
               fit%taken(k) = taken
               exit
            end if
         end do
      end do
   end subroutine ring_fit

   !> Move each ring corner (x(k), y(k)) that lies within ring_snap_reach
   !> (side x sin(theta), or 2 ROUND if more) of a live block's edge, but not
   !> on it, onto the nearest such edge point (onto the edge's corner when
   !> nearer than EDGE to it, if that is within the same reach); theta is 5
   !> degrees, or a quarter of the ring's turn (90/n degrees) on a ring of
   !> more than 18 sides, so that the moved corners keep the ring convex. A joint
   !> grazing the ring (a corner 4 cm past it, sides of 0.58 m, ROUND 0.02)
   !> otherwise crossed two sides at 6 to 9 degrees: the piece between the
   !> joint and the sides was a sliver (merged into the opening) and the rock
   !> outside kept two needle tips whose zones (1/1760 of the mean) set the
   !> time step. With every corner that near the joint on it, the opening's
   !> wall runs along the joint there and each side that leaves the joint
   !> meets it at theta or more: a side from a corner on the line to one
   !> farther than side sin(theta) from it. The opening differs from the
   !> polygon by less than that distance, where the rock would break out to
   !> the joint anyway.
   subroutine snap_to_edges(geo, x, y, reach)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(inout) :: x(:), y(:)
      !> how far a corner may move (ring_snap_reach of the whole ring: an
      !> arc's corners are part of a ring)
      real(wp), intent(in) :: reach
      real(wp), allocatable :: bx(:), by(:)
      integer(ip) :: k, b, q, q2
      real(wp) :: d, t, dbest, qx, qy, el
      if (reach <= 0.0_wp) return
      do k = 1, size(x)
         dbest = reach
         qx = x(k)
         qy = y(k)
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (x(k) < geo%blocks%xmin(b) - reach .or. x(k) > geo%blocks%xmax(b) + reach) cycle
            if (y(k) < geo%blocks%ymin(b) - reach .or. y(k) > geo%blocks%ymax(b) + reach) cycle
            call geometry_block_polygon(geo, b, bx, by)
            do q = 1, size(bx)
               q2 = merge(1_ip, q + 1_ip, q == size(bx))
               call segment_distance(x(k), y(k), bx(q), by(q), bx(q2), by(q2), d, t)
               if (d < dbest) then
                  dbest = d
                  qx = bx(q) + t*(bx(q2) - bx(q))
                  qy = by(q) + t*(by(q2) - by(q))
                  ! nearer than EDGE to the edge's end: onto that corner, as
                  ! a cut end would be (a shorter new edge refuses the cut)
                  el = hypot(bx(q2) - bx(q), by(q2) - by(q))
                  if (t*el < geo%edge_min) then
                     qx = bx(q)
                     qy = by(q)
                  else if ((1.0_wp - t)*el < geo%edge_min) then
                     qx = bx(q2)
                     qy = by(q2)
                  end if
               end if
            end do
         end do
         ! already on an edge (within the geometric tolerance): leave it; a
         ! corner farther than the reach (EDGE is large) is not taken: the
         ! ring would no longer be convex
         if (dbest > 4.0_wp*geo%tol .and. hypot(qx - x(k), qy - y(k)) <= reach) then
            x(k) = qx
            y(k) = qy
         end if
      end do
   end subroutine snap_to_edges

   !> Bend each side of the ring or arc (x, y) (`closed`: back to the first
   !> corner; `side`, `nring`: the whole ring's side and number of sides)
   !> through the block corner it would cut off as a tip too short to cut:
   !> a corner P of a live block lying inside or outside the ring by less
   !> than ring_snap_reach, whose two edges both cross the side, one of them
   !> nearer than EDGE to P (a block outside poking in, or one inside poking
   !> out). The cut's end there is moved
   !> onto P (a shorter piece of edge is refused), and the cut then runs
   !> along P's other edge and cuts nothing: the block kept its tip inside
   !> the ring and the opening did not separate from the rock (session 43's
   !> m5, a 100 m box of joints 1 m and 1.2 m apart: a 24-sided ring of
   !> radius 5 passed 3.7 cm inside a joint crossing at 17.5 degrees to one
   !> joint, and "still crosses 1 block"). With the side bent through P
   !> (the deepest such corner of the side; P is inserted between its
   !> ends, or replaces the nearer end when it lies within EDGE of it, so
   !> that no side is shorter than EDGE), the opening's wall runs through
   !> the joint crossing there: it
   !> differs from the polygon by less than the reach, as snap_to_edges
   !> allows, where the rock would break out to the joints anyway.
   subroutine bend_to_tips(geo, x, y, closed, reach)
      type(geometry_t), intent(in) :: geo
      real(wp), allocatable, intent(inout) :: x(:), y(:)
      logical, intent(in) :: closed
      !> how far a tip may lie off a side (ring_snap_reach of the whole ring)
      real(wp), intent(in) :: reach
      real(wp), allocatable :: bx(:), by(:), nx(:), ny(:)
      integer(ip) :: n, nseg, j, j2, m, b, q, qp, qn, at
      real(wp) :: sgn, ax, ay, ux, uy, el, d, t, dp, dn, legp, legn, best, px, py
      n = size(x, kind=ip)
      if (n < 2) return
      ! inside: right of each side of a clockwise ring, left of a counter-clockwise one
      sgn = merge(1.0_wp, -1.0_wp, polygon_signed_area(x, y) <= 0.0_wp)
      nseg = merge(n, n - 1_ip, closed)
      allocate (nx(2*n), ny(2*n))
      m = 0
      do j = 1, nseg
         m = m + 1
         nx(m) = x(j)
         ny(m) = y(j)
         j2 = modulo(j, n) + 1
         ax = x(j)
         ay = y(j)
         el = hypot(x(j2) - ax, y(j2) - ay)
         if (el <= 2.0_wp*geo%edge_min) cycle
         ux = (x(j2) - ax)/el
         uy = (y(j2) - ay)/el
         best = 4.0_wp*geo%tol
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (min(ax, x(j2)) - reach > geo%blocks%xmax(b) .or. &
                max(ax, x(j2)) + reach < geo%blocks%xmin(b)) cycle
            if (min(ay, y(j2)) - reach > geo%blocks%ymax(b) .or. &
                max(ay, y(j2)) + reach < geo%blocks%ymin(b)) cycle
            call geometry_block_polygon(geo, b, bx, by)
            do q = 1, size(bx, kind=ip)
               d = inward(bx(q), by(q))
               if (abs(d) <= best .or. abs(d) >= reach) cycle
               t = ux*(bx(q) - ax) + uy*(by(q) - ay)
               if (t <= 0.0_wp .or. t >= el) cycle
               qp = merge(size(bx, kind=ip), q - 1_ip, q == 1)
               qn = merge(1_ip, q + 1_ip, q == size(bx))
               dp = inward(bx(qp), by(qp))
               dn = inward(bx(qn), by(qn))
               ! a tip: both edges at P cross the side (a block outside
               ! poking in, or one inside poking out)
               if (dp*d >= 0.0_wp .or. dn*d >= 0.0_wp) cycle
               legp = d/(d - dp)*hypot(bx(qp) - bx(q), by(qp) - by(q))
               legn = d/(d - dn)*hypot(bx(qn) - bx(q), by(qn) - by(q))
               ! both crossings EDGE or more from P: the tip is cut as it is
               if (min(legp, legn) >= geo%edge_min) cycle
               best = abs(d)
               px = bx(q)
               py = by(q)
               ! nearer than EDGE to an end of the side: that end moves onto
               ! P (a bend there would leave a side shorter than EDGE)
               at = 0
               if (t < geo%edge_min) at = 1
               if (t > el - geo%edge_min) at = 2
            end do
         end do
         if (best > 4.0_wp*geo%tol) then
            select case (at)
            case (1)
               nx(m) = px
               ny(m) = py
            case (2)
               x(j2) = px
               y(j2) = py
               if (j2 == 1) then
                  nx(1) = px
                  ny(1) = py
               end if
            case default
               m = m + 1
               nx(m) = px
               ny(m) = py
            end select
         end if
      end do
      if (.not. closed) then
         m = m + 1
         nx(m) = x(n)
         ny(m) = y(n)
      end if
      x = nx(1:m)
      y = ny(1:m)
   contains
      !> How far (px, py) lies inside the side's line (negative: outside).
      pure real(wp) function inward(qx, qy) result(dist)
         real(wp), intent(in) :: qx, qy
         dist = sgn*(uy*(qx - ax) - ux*(qy - ay))
      end function inward
   end subroutine bend_to_tips

   !> How far snap_to_edges may move a corner of a ring of n sides of length
   !> `side`: side x sin(theta), theta = min(5, 90 / n) degrees, or 2 ROUND
   !> if more: the piece between a joint and the two sides past it is that
   !> thick, so 2 A / P, about half the thickness, is below ROUND: a sliver
   !> (split_block_path). DELETE allows as much between an opening's blocks
   !> and its ring.
   pure real(wp) function ring_snap_reach(geo, side, n) result(reach)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: side
      integer(ip), intent(in) :: n
      reach = max(ring_turn_reach(side, n), 2.0_wp*geo%round)
   end function ring_snap_reach

   !> The ring's own snap reach: side x sin(theta), theta = min(5, 90 / n)
   !> degrees, which keeps a ring of n sides convex.
   pure real(wp) function ring_turn_reach(side, n) result(reach)
      real(wp), intent(in) :: side
      integer(ip), intent(in) :: n
      reach = side*sin(min(5.0_wp, 90.0_wp/real(max(n, 3_ip), wp))*pi/180.0_wp)
   end function ring_turn_reach

   !> The live block that holds every corner of polygon (tx, ty) strictly
   !> inside (away from its boundary), 0 if none.
   integer(ip) function enclosing_block(geo, tx, ty) result(found)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: tx(:), ty(:)
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: b, k
      logical :: all_in
      found = 0
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (minval(tx) < geo%blocks%xmin(b) .or. maxval(tx) > geo%blocks%xmax(b)) cycle
         if (minval(ty) < geo%blocks%ymin(b) .or. maxval(ty) > geo%blocks%ymax(b)) cycle
         call geometry_block_polygon(geo, b, x, y)
         all_in = .true.
         do k = 1, size(tx)
            if (.not. point_in_polygon(x, y, tx(k), ty(k)) .or. &
                polygon_boundary_distance(x, y, tx(k), ty(k)) <= 4.0_wp*geo%tol) then
               all_in = .false.
               exit
            end if
         end do
         if (all_in) then
            found = b
            return
         end if
      end do
   end function enclosing_block

   !> Number of live blocks that lie partly inside and partly outside the
   !> convex polygon (tx, ty): 0 when the polygon's inside is made of whole
   !> blocks. A bend of the ring moved onto a joint crossing nearer than
   !> EDGE, or a cut end moved onto a corner, shifts the cut by less than
   !> EDGE: a block this command cut (its corners are newer than corner
   !> `ncorner0`) counts as whole or outside while the smaller of its two
   !> parts is below EDGE times the ring's side. Any other block counts when
   !> its smaller part exceeds 1e-6 of its area: a ring none of whose sides
   !> cut (sides shorter than EDGE) crosses every block it runs through, and
   !> the allowance for shifted cuts made it count 1 of 11.
   integer(ip) function ring_straddling(geo, tx, ty, ncorner0, which) result(count)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: tx(:), ty(:)
      integer(ip), intent(in) :: ncorner0
      integer(ip), intent(inout), optional :: which(:)
      real(wp), allocatable :: x(:), y(:), hx(:), hy(:)
      integer(ip) :: b, k, n, kp, kn
      real(wp) :: inside, area, side, allow, turn, orient
      logical, allocatable :: reflex(:)
      n = size(tx, kind=ip)
      ! the ring bent through a block's tip (bend_to_tips) has reflex
      ! corners: the convex hull less the dent triangles at them
      orient = polygon_signed_area(tx, ty)
      allocate (reflex(n))
      side = 0.0_wp
      do k = 1, n
         kp = merge(n, k - 1_ip, k == 1)
         kn = merge(1_ip, k + 1_ip, k == n)
         turn = (tx(k) - tx(kp))*(ty(kn) - ty(k)) - (ty(k) - ty(kp))*(tx(kn) - tx(k))
         reflex(k) = turn*orient < 0.0_wp
         side = max(side, hypot(tx(kn) - tx(k), ty(kn) - ty(k)))
      end do
      hx = pack(tx, .not. reflex)
      hy = pack(ty, .not. reflex)
      if (orient > 0.0_wp) then
         hx = hx(size(hx):1:-1)
         hy = hy(size(hy):1:-1)
      end if
      count = 0
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%xmax(b) < minval(tx) .or. geo%blocks%xmin(b) > maxval(tx)) cycle
         if (geo%blocks%ymax(b) < minval(ty) .or. geo%blocks%ymin(b) > maxval(ty)) cycle
         call geometry_block_polygon(geo, b, x, y)
         area = geo%blocks%area(b)
         inside = polygon_clip_convex_area(x, y, hx, hy)
         do k = 1, n
            if (.not. reflex(k)) cycle
            kp = merge(n, k - 1_ip, k == 1)
            kn = merge(1_ip, k + 1_ip, k == n)
            inside = inside - polygon_clip_convex_area(x, y, dent([tx(kp), tx(k), tx(kn)], &
                                                                   [ty(kp), ty(k), ty(kn)], 'x'), &
                                                      dent([tx(kp), tx(k), tx(kn)], &
                                                           [ty(kp), ty(k), ty(kn)], 'y'))
         end do
         allow = 1.0e-6_wp*area
         if (geo%blocks%first_corner(b) > ncorner0) allow = max(allow, geo%edge_min*side)
         if (min(inside, area - inside) > allow) then
            count = count + 1
            if (present(which)) then
               if (count <= size(which)) which(count) = b
            end if
         end if
      end do
   contains
      !> Coordinate `c` of the triangle (px, py) made clockwise.
      pure function dent(px, py, c) result(v)
         real(wp), intent(in) :: px(3), py(3)
         character, intent(in) :: c
         real(wp) :: v(3)
         if (polygon_signed_area(px, py) > 0.0_wp) then
            v = merge(px(3:1:-1), py(3:1:-1), c == 'x')
         else
            v = merge(px, py, c == 'x')
         end if
      end function dent
   end function ring_straddling


   !> ARC xc yc xb yb theta npoin: npoin cracks along the arc of the circle
   !> centred at (xc,yc) from (xb,yb), turning theta degrees counter-clockwise.
   !> A full turn (theta = 360 or -360) is a closed ring: it ends exactly
   !> where it began, and where it lies wholly inside one block it is keyed
   !> as TUNNEL's ring is (ring_key_cuts), so that it cuts the opening out.
   !> An arc closing a loop with earlier partial cracks (the second of two
   !> half turns) is keyed the same way (cut_key_pending_loops).
   subroutine joint_arc(geo, xc, yc, xb, yb, theta, npoin, error, out)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: xc, yc, xb, yb, theta
      integer(ip), intent(in) :: npoin
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      integer(ip) :: k, b, kr, kl, npend0, nfull
      real(wp) :: r, a, ak
      real(wp), allocatable :: px(:), py(:), fx(:), fy(:), sx(:), sy(:)
      logical :: closed
      if (.not. geo%block_created) then
         call set_error(error, 'ARC: no BLOCK has been created')
         return
      end if
      r = hypot(xb - xc, yb - yc)
      if (npoin < 1 .or. .not. r > 0.0_wp) then
         call set_error(error, 'ARC: need npoin >= 1 and a start point away from the centre')
         return
      end if
      npend0 = geo%pending%n
      a = atan2(yb - yc, xb - xc)
      allocate (px(0:npoin), py(0:npoin))
      do k = 0, npoin
         ak = a + theta*pi/180.0_wp*real(k, wp)/real(npoin, wp)
         px(k) = xc + r*cos(ak)
         py(k) = yc + r*sin(ak)
      end do
      ! a full turn is a closed ring, as TUNNEL's: it ends where it began
      closed = abs(abs(theta) - 360.0_wp) < 1.0e-9_wp .and. npoin >= 3
      if (.not. closed) then
         ! an end typed to a few decimals where an earlier arc or crack
         ! ended (the second of two half turns: 5.0321 for 5.0320) starts
         ! there: a gap of 1e-4 m kept the two from chaining into a ring
         call join_pending_end(geo, px(0), py(0), min(geo%edge_min, 1.0e-3_wp*r))
         call join_pending_end(geo, px(npoin), py(npoin), min(geo%edge_min, 1.0e-3_wp*r))
      end if
      ! the sides of the whole ring the arc belongs to
      nfull = max(3_ip, nint(real(npoin, wp)*360.0_wp/max(abs(theta), 1.0e-9_wp)))
      b = 0
      if (closed) then
         px(npoin) = px(0)
         py(npoin) = py(0)
         b = enclosing_block(geo, px(0:npoin - 1), py(0:npoin - 1))
         ! corners nearly on a joint are moved onto it, as TUNNEL's are
         ! and small pieces outside it join a neighbour, as TUNNEL's do
         call cut_snapped_ring(geo, px(0:npoin - 1), py(0:npoin - 1), .true., npoin, sx, sy, &
                               error, out, small=[geo%edge_min*hypot(px(1) - px(0), py(1) - py(0)), &
                                                  xc, yc, r, real(npoin, wp)])
      else
         call cut_snapped_ring(geo, px, py, .false., nfull, sx, sy, error, out)
      end if
      if (allocated(error)) return
      if (b > 0) then
         kr = maxloc(sx, 1)
         kl = minloc(sx, 1)
         call ring_key_cuts(geo, b, 'ARC', sx(kr), sy(kr), sx(kl), sy(kl), r, error, out)
      else
         ! with earlier partial cracks (another ARC's half turn) it may
         ! close a loop inside a block
         call cut_key_pending_loops(geo, npend0, 'ARC', error, out)
      end if
      if (allocated(error)) return
      ! the whole circle drawn (this turn, or with earlier arcs on it): rock
      ! wrapped round it is keyed
      if (closed) then
         call cut_key_wrapping_blocks(geo, sx, sy, 'ARC', error, out)
      else if (nfull >= 3 .and. abs(real(nfull, wp)*abs(theta)/360.0_wp - real(npoin, wp)) < &
               1.0e-6_wp) then
         allocate (fx(nfull), fy(nfull))
         do k = 1, nfull
            ak = a + sign(2.0_wp*pi, theta)*real(k - 1, wp)/real(nfull, wp)
            fx(k) = xc + r*cos(ak)
            fy(k) = yc + r*sin(ak)
         end do
         if (ring_drawn(geo, fx, fy)) call cut_key_wrapping_blocks(geo, fx, fy, 'ARC', error, out)
      end if
   end subroutine joint_arc

   !> Move (x, y) onto the nearest end of a pending crack segment within
   !> `reach` of it, if there is one not already within the tolerance.
   subroutine join_pending_end(geo, x, y, reach)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(inout) :: x, y
      real(wp), intent(in) :: reach
      real(wp) :: best, qx, qy
      integer(ip) :: i
      best = reach
      qx = x
      qy = y
      do i = 1, geo%pending%n
         call nearer(geo%pending%x1(i), geo%pending%y1(i))
         call nearer(geo%pending%x2(i), geo%pending%y2(i))
      end do
      if (best > geo%tol) then
         x = qx
         y = qy
      end if
   contains
      subroutine nearer(ex, ey)
         real(wp), intent(in) :: ex, ey
         real(wp) :: d
         d = hypot(ex - x, ey - y)
         if (d < best) then
            best = d
            qx = ex
            qy = ey
         end if
      end subroutine nearer
   end subroutine join_pending_end

   !> Does every side of the ring (x, y) run along block edges (its midpoint
   !> within EDGE, or the snap reach, of one: cutting moves a ring's bends
   !> by up to that)?
   logical function ring_drawn(geo, x, y) result(drawn)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x(:), y(:)
      real(wp), allocatable :: bx(:), by(:)
      real(wp) :: mx, my, reach
      integer(ip) :: k, b, n
      logical :: on
      n = size(x, kind=ip)
      reach = max(geo%edge_min, ring_snap_reach(geo, hypot(x(2) - x(1), y(2) - y(1)), n))
      drawn = .false.
      do k = 1, n
         mx = 0.5_wp*(x(k) + x(modulo(k, n) + 1))
         my = 0.5_wp*(y(k) + y(modulo(k, n) + 1))
         on = .false.
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (mx < geo%blocks%xmin(b) - reach .or. mx > geo%blocks%xmax(b) + reach) cycle
            if (my < geo%blocks%ymin(b) - reach .or. my > geo%blocks%ymax(b) + reach) cycle
            call geometry_block_polygon(geo, b, bx, by)
            if (polygon_boundary_distance(bx, by, mx, my) <= reach) then
               on = .true.
               exit
            end if
         end do
         if (.not. on) return
      end do
      drawn = .true.
   end function ring_drawn

end module geometry_joint_sets
