!> Creating and cutting blocks (manual Section 4.2 II; commands BLOCK, SPLIT,
!> CRACK, JDELETE, DELETE, ROUND, EDGE).
!>
!> Every cut is a straight segment. Inside one block the segment falls into
!> pieces; a piece with both ends on the block boundary (a chord) splits the
!> block in two. CRACK keeps the segment in a pending list when some piece
!> ends inside a block (a partially-penetrating crack, manual 5.2.1); after
!> each crack the pending segments of the blocks it touched are searched for
!> a chain of crack pieces running from boundary to boundary, which then
!> splits the block. `cut_remove_partial` forgets what is left (first CYCLE,
!> first GENERATE, JDELETE).
!>
!> Short edges and slivers (manual EDGE / SET EDGE): a cut end that would
!> leave a piece of its edge shorter than the minimum edge `edge_min` is moved
!> onto the nearer corner, and a bend of a crack path nearer than `edge_min`
!> to the previous point or the path's end is moved onto it. A split whose new
!> edges would still be shorter than `edge_min`, or whose pieces would be
!> slivers (area < 0.1*edge_min**2, or 2*area/perimeter below the rounding
!> length), is refused (counted in `geo%cut_stats`, a note under SET LOG ON):
!> such blocks never reach the mechanics. Each block is cut independently
!> within its own boundary, so block areas always add up to the parent.
module geometry_cutting
   use model_address, only: address_split
   use core_sort, only: sort_order, sort_order_pairs, sort_values
   use core_arrays, only: grow_lists, push_back
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t, set_error
   use core_output, only: output_t, itoa, format_real
   use geometry_polygon, only: polygon_signed_area, point_in_polygon, segment_distance, &
                               polygon_boundary_distance, polygon_is_simple, segment_intersection, &
                               require_clockwise_simple, polygon_centroid, polygon_clip_convex_area
   use core_constants, only: pi
   use model_geometry, only: geometry_t, geometry_tol_rel, geometry_end_rel, geometry_block_polygon, &
                             geometry_kill_block, geometry_add_pending, geometry_add_jplot, &
                             geometry_live_blocks, &
                             jplot_list_t, jplot_list_add, &
                             cut_made, cut_snapped, cut_bend_moved, cut_touch, &
                             cut_refused_short, cut_refused_sliver, cut_refused_shape, &
                             cut_sliver_merged
   use geometry_blocks, only: geometry_add_block, geometry_set_block_polygon, &
                              geometry_update_rounding
   implicit none
   private
   public :: cut_create_block, cut_create_circular, cut_split, cut_crack
   public :: cut_remove_partial, cut_delete_range, cut_delete_block
   public :: cut_set_round, cut_set_edge, cut_segment_pieces, cut_apply_segment
   public :: mode_split, mode_crack, ring_polygon, ring_key_cuts, cut_key_pending_loops, &
             cut_key_wrapping_blocks
   public :: rjoint_on, rjoint_traces

   !> SET WRITE (manual 4.5, "writes 'scratch' joint file to RJOINT"): while
   !> on, CRACK and JSET also record their traces inside the blocks here; the
   !> command writes them to RJOINT and empties the list. A setting of the
   !> session, like SET LOG, not of the model (not saved).
   logical, save :: rjoint_on = .false.
   type(jplot_list_t), save :: rjoint_traces

   integer(ip), parameter :: mode_split = 1, mode_crack = 2

   !> One piece of a segment inside a block, with where its ends lie:
   !> edge index (0 = inside the block) and corner index (0 = not a corner).
   type :: piece_t
      real(wp) :: xa, ya, xb, yb
      integer(ip) :: edge_a, edge_b, vert_a, vert_b
      real(wp) :: s_a, s_b            !< parameter along edge_a / edge_b
      logical :: moved_a = .false., moved_b = .false.   !< end moved onto a corner
   end type piece_t

contains

   !> BLOCK x1 y1 x2 y2 ...: the first (and only) block, corners clockwise.
   subroutine cut_create_block(geo, x, y, material, cons, error)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x(:), y(:)
      integer(ip), intent(in) :: material, cons
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: extent, tol
      integer(ip) :: id
      if (geo%block_created) then
         call set_error(error, 'BLOCK: only one BLOCK command may be used per run (manual Section 4.5); '// &
                        'cut further blocks from it with CRACK, SPLIT, TUNNEL, ARC or JSET and DELETE '// &
                        'the unwanted ones, or START a new problem')
         return
      end if
      if (size(x) < 3 .or. size(x) /= size(y)) then
         call set_error(error, 'BLOCK: at least 3 corners are needed')
         return
      end if
      extent = max(maxval(x) - minval(x), maxval(y) - minval(y))
      if (.not. extent > 0.0_wp) then
         call set_error(error, 'BLOCK: corners do not span an area')
         return
      end if
      tol = geometry_tol_rel*extent
      call require_clockwise_simple(x, y, tol, 'BLOCK', &
                                    'the boundary intersects itself or repeats a corner', error)
      if (allocated(error)) return
      geo%extent = extent
      geo%tol = tol
      call geometry_add_block(geo, x, y, material, cons, id)
      geo%original_area = geo%blocks%area(id)
      geo%block_created = .true.
   end subroutine cut_create_block

   !> BLOCK CIRCULAR xc yc r n: a regular n-gon inscribed in the circle.
   subroutine cut_create_circular(geo, xc, yc, r, n, material, cons, error)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: xc, yc, r
      integer(ip), intent(in) :: n, material, cons
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: k
      if (n < 3 .or. .not. r > 0.0_wp) then
         call set_error(error, 'BLOCK CIRCULAR: need r > 0 and at least 3 edges')
         return
      end if
      allocate (x(n), y(n))
      do k = 1, n
         ! decreasing angle gives clockwise order
         x(k) = xc + r*cos(-2.0_wp*pi*real(k - 1, wp)/real(n, wp))
         y(k) = yc + r*sin(-2.0_wp*pi*real(k - 1, wp)/real(n, wp))
      end do
      call cut_create_block(geo, x, y, material, cons, error)
   end subroutine cut_create_circular

   !> ROUND d. The minimum edge follows (2*d) unless EDGE set a larger one.
   subroutine cut_set_round(geo, d, error)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: d
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b
      if (.not. d > 0.0_wp) then
         call set_error(error, 'ROUND: the rounding length must be positive')
         return
      end if
      geo%round = d
      if (.not. geo%edge_set .or. geo%edge_min < 2.0_wp*d) geo%edge_min = 2.0_wp*d
      do b = 1, geo%blocks%n
         if (geo%blocks%live(b)) call geometry_update_rounding(geo, b)
      end do
      geo%contacts_valid = .false.
   end subroutine cut_set_round

   !> EDGE emin (also SET EDGE): emin >= 2*round.
   subroutine cut_set_edge(geo, emin, error)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: emin
      type(error_t), allocatable, intent(out) :: error
      if (emin < 2.0_wp*geo%round) then
         ! the values, so the user sees which to change (camp11)
         call set_error(error, 'EDGE: emin '//format_real(emin)//' is below twice the '// &
                        'rounding length (ROUND '//format_real(geo%round)//'): give EDGE >= '// &
                        format_real(2.0_wp*geo%round)//' or a smaller ROUND first')
         return
      end if
      geo%edge_min = emin
      geo%edge_set = .true.
   end subroutine cut_set_edge

   !> SPLIT x1 y1 x2 y2: split every block the segment fully crosses.
   subroutine cut_split(geo, x1, y1, x2, y2, error, out)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      if (.not. geo%block_created) then
         call set_error(error, 'SPLIT: no BLOCK has been created')
         return
      end if
      call cut_apply_segment(geo, x1, y1, x2, y2, mode_split, out)
   end subroutine cut_split

   !> CRACK x1 y1 x2 y2 <JREG>: a crack that may end inside a block. It is
   !> limited to the last JREGION when `in_jregion`, and stops at the
   !> periphery of the last tunnel. With `jplot` true (CRACK and JSET, the
   !> commands JPLOT previews) and JPLOT recording on, the pieces inside live
   !> blocks are recorded in `geo%jplot` and no block is cut.
   subroutine cut_crack(geo, x1, y1, x2, y2, in_jregion, error, out, jplot, merge_below)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: x1, y1, x2, y2
      logical, intent(in) :: in_jregion
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      logical, intent(in), optional :: jplot
      !> TUNNEL's ring [area, xc, yc, r, n]: a piece of a cut outside the
      !> ring smaller than area (EDGE x its side), the other piece not, is
      !> merged into a neighbour where it can be
      real(wp), intent(in), optional :: merge_below(5)
      real(wp), allocatable :: t0(:), t1(:), u0(:), u1(:), tx(:), ty(:)
      integer(ip) :: n, m, i, j, k, nt
      real(wp) :: dx, dy
      logical :: preview
      if (.not. geo%block_created) then
         call set_error(error, 'CRACK: no BLOCK has been created')
         return
      end if
      if (in_jregion .and. .not. geo%has_jregion) then
         call set_error(error, 'CRACK JREG: no JREGION has been defined')
         return
      end if
      dx = x2 - x1
      dy = y2 - y1
      ! parameter intervals of the segment that survive the region and tunnel
      allocate (t0(1), t1(1))
      t0 = 0.0_wp
      t1 = 1.0_wp
      n = 1
      if (in_jregion) then
         call cut_segment_pieces(geo%jregion_x, geo%jregion_y, x1, y1, x2, y2, geo%tol, &
                                 .true., t0, t1, n)
      end if
      nt = geo%tunnels%n
      if (nt > 0) then
         if (geo%tunnels%r(nt) > 0.0_wp) then
            call tunnel_polygon(geo, nt, tx, ty)
            allocate (u0(0), u1(0))
            m = 0
            do i = 1, n
               call clip_outside(tx, ty, i)
            end do
            call move_alloc(u0, t0)
            call move_alloc(u1, t1)
            n = m
         end if
      end if
      preview = geo%jplot%on
      if (present(jplot)) then
         preview = preview .and. jplot
      else
         preview = .false.
      end if
      do i = 1, n
         ! SET WRITE: the trace goes to RJOINT too (CRACK, JSET)
         if (rjoint_on .and. present(jplot)) then
            if (jplot) call record_jplot(geo, x1 + t0(i)*dx, y1 + t0(i)*dy, x1 + t1(i)*dx, &
                                         y1 + t1(i)*dy, rjoint=.true.)
         end if
         if (preview) then
            call record_jplot(geo, x1 + t0(i)*dx, y1 + t0(i)*dy, x1 + t1(i)*dx, y1 + t1(i)*dy)
         else
            call cut_apply_segment(geo, x1 + t0(i)*dx, y1 + t0(i)*dy, x1 + t1(i)*dx, &
                                   y1 + t1(i)*dy, mode_crack, out, merge_below)
         end if
      end do
   contains
      subroutine clip_outside(px, py, i)
         real(wp), intent(in) :: px(:), py(:)
         integer(ip), intent(in) :: i
         real(wp), allocatable :: s0(:), s1(:), w(:)
         integer(ip) :: ns
         real(wp) :: ax, ay, bx, by
         ax = x1 + t0(i)*dx
         ay = y1 + t0(i)*dy
         bx = x1 + t1(i)*dx
         by = y1 + t1(i)*dy
         call cut_segment_pieces(px, py, ax, ay, bx, by, geo%tol, .false., s0, s1, ns)
         do j = 1, ns
            k = m + 1
            allocate (w(k)); w(1:m) = u0(1:m); call move_alloc(w, u0)
            allocate (w(k)); w(1:m) = u1(1:m); call move_alloc(w, u1)
            u0(k) = t0(i) + s0(j)*(t1(i) - t0(i))
            u1(k) = t0(i) + s1(j)*(t1(i) - t0(i))
            m = k
         end do
      end subroutine clip_outside
   end subroutine cut_crack

   !> JPLOT: record the pieces of segment a-b inside live blocks, cutting nothing.
   subroutine record_jplot(geo, ax, ay, bx, by, rjoint)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: ax, ay, bx, by
      logical, intent(in), optional :: rjoint   !< record in rjoint_traces (SET WRITE)
      integer(ip), allocatable :: list(:)
      integer(ip) :: nlist, k, b, i, np
      real(wp), allocatable :: x(:), y(:), t0(:), t1(:)
      if (hypot(bx - ax, by - ay) <= geo%tol) return
      call blocks_along(geo, ax, ay, bx, by, list, nlist)
      do k = 1, nlist
         b = list(k)
         call geometry_block_polygon(geo, b, x, y)
         call cut_segment_pieces(x, y, ax, ay, bx, by, geo%tol, .true., t0, t1, np)
         do i = 1, np
            if (present(rjoint)) then
               call jplot_list_add(rjoint_traces, ax + t0(i)*(bx - ax), ay + t0(i)*(by - ay), &
                                   ax + t1(i)*(bx - ax), ay + t1(i)*(by - ay), b)
               cycle
            end if
            call geometry_add_jplot(geo, ax + t0(i)*(bx - ax), ay + t0(i)*(by - ay), &
                                    ax + t1(i)*(bx - ax), ay + t1(i)*(by - ay), b)
         end do
      end do
   end subroutine record_jplot

   !> The polygon of tunnel `k` (clockwise).
   subroutine tunnel_polygon(geo, k, x, y)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: k
      real(wp), allocatable, intent(out) :: x(:), y(:)
      call ring_polygon(geo%tunnels%xc(k), geo%tunnels%yc(k), geo%tunnels%r(k), &
                        geo%tunnels%nside(k), x, y)
   end subroutine tunnel_polygon

   !> The n corners of a TUNNEL ring of radius r about (xc, yc), clockwise
   !> from angle 0.
   pure subroutine ring_polygon(xc, yc, r, n, x, y)
      real(wp), intent(in) :: xc, yc, r
      integer(ip), intent(in) :: n
      real(wp), allocatable, intent(out) :: x(:), y(:)
      integer(ip) :: i
      allocate (x(n), y(n))
      do i = 1, n
         x(i) = xc + r*cos(-2.0_wp*pi*real(i - 1, wp)/real(n, wp))
         y(i) = yc + r*sin(-2.0_wp*pi*real(i - 1, wp)/real(n, wp))
      end do
   end subroutine ring_polygon

   !> A block cannot have a hole: a closed ring (TUNNEL, ARC of 360 degrees)
   !> lying wholly inside block b is keyed by two horizontal cracks, from its
   !> rightmost corner (xr, yr) and a leftmost one (xl, yl) out to the
   !> block's edges, so that the ring separates the opening (with a note
   !> naming the command `what`); r is the ring's radius. `loop` (optional):
   !> a closed loop of partial cracks, not a ring, is keyed (the note says so).
   subroutine ring_key_cuts(geo, b, what, xr, yr, xl, yl, r, error, out, loop)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: b
      character(len=*), intent(in) :: what
      real(wp), intent(in) :: xr, yr, xl, yl, r
      type(error_t), allocatable, intent(inout) :: error
      type(output_t), intent(in), optional :: out
      logical, intent(in), optional :: loop
      character(len=:), allocatable :: shape
      logical :: made
      call key_cut(geo, xr, yr, 1.0_wp, 0.0_wp, r, 0_ip, made, error, out)
      if (allocated(error)) return
      call key_cut(geo, xl, yl, -1.0_wp, 0.0_wp, r, 0_ip, made, error, out)
      if (allocated(error)) return
      shape = 'the ring'
      if (present(loop)) then
         if (loop) shape = 'the closed loop of partial cracks'
      end if
      if (present(out)) call out%line('Note: '//what//': '//shape//' lay inside one block, '// &
         'which has been cut along horizontal lines from its sides to the block''s edges '// &
         '(a block cannot hold a hole)')
   end subroutine ring_key_cuts

   !> A crack from ring corner (vx, vy) along the unit direction (ux, uy)
   !> to where it leaves the block just outside the ring there (r: the
   !> ring's size); `only` > 0: only if that block is block `only`. `made`:
   !> a crack was laid. Starting at a corner of the ring (not on one of its
   !> sides) lets the crack pieces chain up. The block is found again for
   !> each cut: the ring's cracks or a first key, completing partial cracks
   !> of a JSET with gaps, may have cut a piece off the block (a corner of
   !> the model) and so renumbered it; the key was then skipped and the ring
   !> never separated. `wall` (optional, the ring's sides are block edges):
   !> the crack starts where the line through the corner leaves the ring's
   !> wall, if within `wall` back along it: the corner of a ring drawn again
   !> (the whole circle of two half ARCs, typed to radii 5.673 and 5.674)
   !> may lie 1 mm inside the block, and a crack from there out to its
   !> edge stayed partial and cut nothing (fuzz quick seed 151).
   subroutine key_cut(geo, vx, vy, ux, uy, r, only, made, error, out, wall)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: vx, vy, ux, uy, r
      integer(ip), intent(in) :: only
      logical, intent(out) :: made
      type(error_t), allocatable, intent(inout) :: error
      type(output_t), intent(in), optional :: out
      real(wp), intent(in), optional :: wall
      real(wp), allocatable :: x(:), y(:), t0(:), t1(:)
      real(wp) :: far, px, py, back, sx, sy
      integer(ip) :: np, bk, k
      made = .false.
      px = vx + ux*1.0e-3_wp*r
      py = vy + uy*1.0e-3_wp*r
      bk = 0
      do k = 1, geo%blocks%n
         if (.not. geo%blocks%live(k)) cycle
         if (px < geo%blocks%xmin(k) .or. px > geo%blocks%xmax(k)) cycle
         if (py < geo%blocks%ymin(k) .or. py > geo%blocks%ymax(k)) cycle
         call geometry_block_polygon(geo, k, x, y)
         if (point_in_polygon(x, y, px, py)) then
            bk = k
            exit
         end if
      end do
      if (bk == 0 .or. (only > 0 .and. bk /= only)) return
      call geometry_block_polygon(geo, bk, x, y)
      far = 2.0_wp*(geo%blocks%xmax(bk) - geo%blocks%xmin(bk) + geo%blocks%ymax(bk) - &
                    geo%blocks%ymin(bk)) + 2.0_wp*r
      sx = vx
      sy = vy
      if (present(wall)) then
         ! the piece of the line in the block that holds the corner's
         ! neighbour point, from up to `wall` back along it
         back = wall
         call cut_segment_pieces(x, y, vx - ux*back, vy - uy*back, vx + ux*far, vy + uy*far, &
                                 geo%tol, .true., t0, t1, np)
         do k = 1, np
            if (t0(k)*(back + far) <= back + 1.0e-3_wp*r .and. &
                t1(k)*(back + far) >= back + 1.0e-3_wp*r) then
               sx = vx - ux*back + ux*(back + far)*t0(k)
               sy = vy - uy*back + uy*(back + far)*t0(k)
               exit
            end if
         end do
      end if
      call cut_segment_pieces(x, y, sx, sy, sx + ux*far, sy + uy*far, geo%tol, .true., t0, t1, np)
      if (np < 1) return
      call cut_crack(geo, sx, sy, sx + ux*far*t1(1), sy + uy*far*t1(1), .false., error, out)
      made = .not. allocated(error)
   end subroutine key_cut

   !> After a closed ring (rx, ry) is cut: a block of rock outside it that
   !> wraps round it, so that its centroid lies inside the ring (a strip the
   !> ring enters and leaves through one joint: a U round the opening), is
   !> what a user's DELETE of the opening would take with it (manual Section
   !> 4.5: every block whose centroid is in the range), and it nearly holds
   !> a hole. It is cut by a key, as a ring inside one block is
   !> (ring_key_cuts): a crack from the ring corner towards the block's
   !> centroid, straight out from the ring's centre to the block's edge,
   !> through the middle of the U. A block counts as outside the ring when
   !> more than half of it lies outside. At most 4 keys a block.
   subroutine cut_key_wrapping_blocks(geo, rx, ry, what, error, out)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: rx(:), ry(:)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      type(output_t), intent(in), optional :: out
      real(wp), allocatable :: cx(:), cy(:), x(:), y(:)
      real(wp) :: xc, yc, r, bx, by, area, inside, d, ux, uy
      integer(ip) :: b, k, tries, nkey, made0, left
      logical :: made
      cx = rx
      cy = ry
      if (polygon_signed_area(cx, cy) > 0.0_wp) then
         cx = cx(size(cx):1:-1)
         cy = cy(size(cy):1:-1)
      end if
      xc = sum(cx)/size(cx)
      yc = sum(cy)/size(cy)
      r = maxval(hypot(cx - xc, cy - yc))
      nkey = 0
      left = 0
      b = 0
      tries = 0
      do while (b < geo%blocks%n)
         b = b + 1
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%xmax(b) < minval(cx) .or. geo%blocks%xmin(b) > maxval(cx)) cycle
         if (geo%blocks%ymax(b) < minval(cy) .or. geo%blocks%ymin(b) > maxval(cy)) cycle
         call geometry_block_polygon(geo, b, x, y)
         call polygon_centroid(x, y, bx, by, area)
         area = abs(area)
         if (.not. point_in_polygon(cx, cy, bx, by)) cycle
         inside = polygon_clip_convex_area(x, y, cx, cy)
         if (inside > 0.5_wp*area) cycle
         d = hypot(bx - xc, by - yc)
         if (d > 1.0e-6_wp*r) then
            ux = (bx - xc)/d
            uy = (by - yc)/d
         else
            ux = 1.0_wp
            uy = 0.0_wp
         end if
         k = maxloc((cx - xc)*ux + (cy - yc)*uy, 1)
         ! the key starts on the ring's wall, which lies off the corner by
         ! less than the ring's snap (the corners are moved by less than
         ! 0.1 r, docs/geometry.md)
         made0 = geo%cut_stats(cut_made)
         call key_cut(geo, cx(k), cy(k), ux, uy, r, b, made, error, out, wall=0.1_wp*r)
         if (allocated(error)) return
         ! a crack laid that cut nothing (it stays partial) is not a key
         made = geo%cut_stats(cut_made) > made0
         if (made) nkey = nkey + 1
         ! its pieces may wrap the ring still
         if (made .and. tries < 4) then
            tries = tries + 1
            b = b - 1
         else
            if (.not. made) left = b
            tries = 0
         end if
      end do
      if (nkey > 0 .and. present(out)) call out%line('Note: '//what//': '//itoa(nkey)// &
         ' key cut(s) through rock wrapped round the ring (its centroid inside the ring, '// &
         'which DELETE of the opening would take): straight out from the ring''s centre')
      if (left > 0 .and. present(out)) call out%line('Warning: '//what//': block '// &
         itoa(left)//' wraps round the ring (its centroid inside it) and its key cut '// &
         'nothing: DELETE of the opening would take it')
   end subroutine cut_key_wrapping_blocks

   !> Partial cracks closing a loop inside one block (two ARCs of 180
   !> degrees, four CRACKs drawing a square) separate nothing: a block cannot
   !> hold a hole. Such a loop holding a piece of a pending segment numbered
   !> above `npend0` (the command `what` laid it) is keyed as a TUNNEL ring
   !> is (ring_key_cuts), so that it cuts out what it encloses. Each block
   !> is examined again after keys that cut it, at most four times.
   subroutine cut_key_pending_loops(geo, npend0, what, error, out)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: npend0
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      type(output_t), intent(in), optional :: out
      real(wp), allocatable :: x(:), y(:), px(:), py(:)
      real(wp) :: loop(5), sa, sb
      integer(ip) :: b, ea, va, eb, vb, again, i, nlive
      logical :: found, near
      if (geo%pending%n <= npend0) return
      b = 0
      again = 0
      nlive = geometry_live_blocks(geo)
      do while (b < geo%blocks%n)
         b = b + 1
         if (.not. geo%blocks%live(b)) cycle
         near = .false.
         do i = npend0 + 1, geo%pending%n
            if (max(geo%pending%x1(i), geo%pending%x2(i)) < geo%blocks%xmin(b)) cycle
            if (min(geo%pending%x1(i), geo%pending%x2(i)) > geo%blocks%xmax(b)) cycle
            if (max(geo%pending%y1(i), geo%pending%y2(i)) < geo%blocks%ymin(b)) cycle
            if (min(geo%pending%y1(i), geo%pending%y2(i)) > geo%blocks%ymax(b)) cycle
            near = .true.
            exit
         end do
         if (.not. near) cycle
         call geometry_block_polygon(geo, b, x, y)
         call find_pending_path(geo, b, x, y, 0_ip, px, py, ea, va, sa, eb, vb, sb, found, &
                                newfrom=npend0, loop=loop)
         if (found .or. .not. loop(5) > 0.0_wp) cycle
         call ring_key_cuts(geo, b, what, loop(1), loop(2), loop(3), loop(4), loop(5), error, &
                            out, loop=.true.)
         if (allocated(error)) return
         ! the block's remains may hold another loop, if the keys cut it
         if (geometry_live_blocks(geo) > nlive .and. again < 4) then
            again = again + 1
            b = b - 1
         else
            again = 0
         end if
         nlive = geometry_live_blocks(geo)
      end do
   end subroutine cut_key_pending_loops

   !> JDELETE (and the first CYCLE / GENERATE): forget crack segments that
   !> did not separate blocks.
   !> The note counts the segments that still end inside a block: a pending
   !> segment that a later crack completed (`CRACK 0,3 2,1` then `CRACK 2,1
   !> 4,3` cuts a V) lies along the edges it made and is no partial crack.
   subroutine cut_remove_partial(geo, out)
      type(geometry_t), intent(inout) :: geo
      type(output_t), intent(in), optional :: out
      real(wp), allocatable :: box(:, :), x(:), y(:)
      integer(ip) :: i, b, ndangle
      if (geo%pending%n > 0 .and. present(out)) then
         ! the blocks' boxes from their outlines (the stored ones are made
         ! anew only after the geometry commands)
         allocate (box(4, geo%blocks%n))
         box = 0.0_wp
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            call geometry_block_polygon(geo, b, x, y)
            box(:, b) = [minval(x), maxval(x), minval(y), maxval(y)]
         end do
         ndangle = 0
         do i = 1, geo%pending%n
            if (pending_dangles(geo, i, box)) ndangle = ndangle + 1
         end do
         if (ndangle > 0) call out%line('Note: '//itoa(ndangle)// &
                                        ' partial crack segment(s) not separating blocks deleted')
      end if
      geo%pending%n = 0
   end subroutine cut_remove_partial

   !> Does pending segment i run inside a live block anywhere (sampled at
   !> eight points), farther from its outline than the cut-line tolerance?
   !> `box`: each block's xmin xmax ymin ymax.
   logical function pending_dangles(geo, i, box)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      real(wp), intent(in) :: box(:, :)
      integer, parameter :: nsample = 8
      real(wp), allocatable :: x(:), y(:)
      real(wp) :: px, py, t, tol
      integer(ip) :: b
      integer :: k
      pending_dangles = .false.
      tol = cut_line_tol(geo)
      associate (bl => geo%blocks, pe => geo%pending)
         do k = 1, nsample
            t = (real(k, wp) - 0.5_wp)/real(nsample, wp)
            px = pe%x1(i) + t*(pe%x2(i) - pe%x1(i))
            py = pe%y1(i) + t*(pe%y2(i) - pe%y1(i))
            do b = 1, bl%n
               if (.not. bl%live(b)) cycle
               if (px < box(1, b) .or. px > box(2, b) .or. py < box(3, b) .or. &
                   py > box(4, b)) cycle
               call geometry_block_polygon(geo, b, x, y)
               if (.not. point_in_polygon(x, y, px, py)) cycle
               if (polygon_boundary_distance(x, y, px, py) > tol) then
                  pending_dangles = .true.
                  return
               end if
            end do
         end do
      end associate
   end function pending_dangles

   !> DELETE xl xu yl yu <AREA armin>: blocks whose centroid is strictly
   !> inside the range (and whose area is below armin when given).
   subroutine cut_delete_range(geo, xl, xu, yl, yu, ndeleted, armin)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: xl, xu, yl, yu
      integer(ip), intent(out) :: ndeleted
      real(wp), intent(in), optional :: armin
      integer(ip) :: b
      ndeleted = 0
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         associate (xc => geo%blocks%xc(b), yc => geo%blocks%yc(b))
            if (.not. (xc > xl .and. xc < xu .and. yc > yl .and. yc < yu)) cycle
         end associate
         if (present(armin)) then
            if (.not. geo%blocks%area(b) < armin) cycle
         end if
         call geometry_kill_block(geo, b)
         ndeleted = ndeleted + 1
      end do
   end subroutine cut_delete_range

   !> DELETE BLOCK n.
   subroutine cut_delete_block(geo, id, error)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: id
      type(error_t), allocatable, intent(out) :: error
      character(len=60) :: text
      if (id < 1 .or. id > geo%blocks%n) then
         write (text, '(a,i0)') 'DELETE BLOCK: no block ', id
         call set_error(error, trim(text))
         return
      end if
      if (.not. geo%blocks%live(id)) then
         write (text, '(a,i0,a)') 'DELETE BLOCK: block ', id, ' is already deleted'
         call set_error(error, trim(text))
         return
      end if
      call geometry_kill_block(geo, id)
   end subroutine cut_delete_block

   !> Parameter intervals [t0,t1] of segment a-b lying strictly inside
   !> (`inside`) or strictly outside the polygon x,y.
   subroutine cut_segment_pieces(x, y, ax, ay, bx, by, tol, inside, t0, t1, n, online)
      real(wp), intent(in) :: x(:), y(:), ax, ay, bx, by, tol
      logical, intent(in) :: inside
      real(wp), allocatable, intent(out) :: t0(:), t1(:)
      integer(ip), intent(out) :: n
      !> a corner this near the segment lies on it, a piece whose middle is
      !> this near the outline runs along it (default tol; cut_line_tol)
      real(wp), intent(in), optional :: online
      real(wp), allocatable :: t(:)
      integer(ip) :: nt, i
      real(wp) :: mx, my, len, on
      logical :: in
      len = hypot(bx - ax, by - ay)
      n = 0
      allocate (t0(0), t1(0))
      if (len <= tol) return
      on = tol
      if (present(online)) on = max(tol, online)
      call crossing_params(x, y, ax, ay, bx, by, tol, on, t, nt)
      deallocate (t0, t1)
      allocate (t0(nt), t1(nt))
      do i = 1, nt - 1
         if ((t(i + 1) - t(i))*len <= tol) cycle
         mx = ax + 0.5_wp*(t(i) + t(i + 1))*(bx - ax)
         my = ay + 0.5_wp*(t(i) + t(i + 1))*(by - ay)
         if (polygon_boundary_distance(x, y, mx, my) <= on) cycle
         in = point_in_polygon(x, y, mx, my)
         if (in .neqv. inside) cycle
         n = n + 1
         t0(n) = t(i)
         t1(n) = t(i + 1)
      end do
   end subroutine cut_segment_pieces

   !> Sorted distinct parameters (0 and 1 included) where segment a-b meets
   !> the polygon boundary (distinct: farther apart than tol); corners within
   !> `on` of the segment are points of it.
   subroutine crossing_params(x, y, ax, ay, bx, by, tol, on, t, nt)
      real(wp), intent(in) :: x(:), y(:), ax, ay, bx, by, tol, on
      real(wp), allocatable, intent(out) :: t(:)
      integer(ip), intent(out) :: nt
      integer(ip) :: i, j, n, k
      real(wp) :: s, u, d, len, tv, dj, tj
      logical :: hit
      n = size(x)
      len = hypot(bx - ax, by - ay)
      allocate (t(2*n + 2))
      nt = 2
      t(1) = 0.0_wp
      t(2) = 1.0_wp
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         ! corners on the segment: touches and collinear overlaps
         call segment_distance(x(i), y(i), ax, ay, bx, by, d, tv)
         if (d <= on) then
            nt = nt + 1
            t(nt) = tv
         end if
         ! an edge whose two corners lie on the segment lies along it: where
         ! the two lines cross within their typed digits (the edge a few
         ! 1e-5 off the cut's line) is no crossing, and would open a sliver
         ! of the block between them to the cut
         call segment_distance(x(j), y(j), ax, ay, bx, by, dj, tj)
         if (d <= on .and. dj <= on) cycle
         call segment_intersection(ax, ay, bx, by, x(i), y(i), x(j), y(j), hit, s, u)
         if (hit) then
            nt = nt + 1
            t(nt) = s
         end if
      end do
      ! sort, then drop near-duplicates
      call sort_values(t(1:nt))
      k = 1
      do i = 2, nt
         if ((t(i) - t(k))*len > tol) then
            k = k + 1
            t(k) = t(i)
         end if
      end do
      t(k) = 1.0_wp
      nt = k
   end subroutine crossing_params

   !> Pieces of segment a-b inside block polygon x,y with their end locations.
   subroutine block_pieces(geo, x, y, ax, ay, bx, by, pieces, np)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x(:), y(:), ax, ay, bx, by
      type(piece_t), allocatable, intent(out) :: pieces(:)
      integer(ip), intent(out) :: np
      real(wp), allocatable :: t0(:), t1(:)
      integer(ip) :: i
      real(wp) :: near_end, online
      ! a corner this close to the cut's line lies on it (cut_line_tol)
      online = cut_line_tol(geo)
      call cut_segment_pieces(x, y, ax, ay, bx, by, geo%tol, .true., t0, t1, np, online)
      allocate (pieces(np))
      ! a typed end of the segment inside the block but within
      ! geometry_end_rel of an edge is a point of that edge
      near_end = max(4.0_wp*geo%tol, geometry_end_rel*geo%extent)
      do i = 1, np
         associate (p => pieces(i))
            p%xa = ax + t0(i)*(bx - ax)
            p%ya = ay + t0(i)*(by - ay)
            p%xb = ax + t1(i)*(bx - ax)
            p%yb = ay + t1(i)*(by - ay)
            call locate_on_boundary(geo, x, y, p%xa, p%ya, p%edge_a, p%vert_a, p%s_a, &
                                    p%moved_a, merge(near_end, 2.0_wp*online, t0(i) <= 0.0_wp))
            call locate_on_boundary(geo, x, y, p%xb, p%yb, p%edge_b, p%vert_b, p%s_b, &
                                    p%moved_b, merge(near_end, 2.0_wp*online, t1(i) >= 1.0_wp))
         end associate
      end do
   end subroutine block_pieces

   !> How near a block corner must lie to a cut's line (SPLIT, CRACK, JSET,
   !> ARC, TUNNEL) to be a point of it: 1 % of the minimum edge, at least the
   !> geometric tolerance. A user puts a block on an inclined plane by typing
   !> the plane's corners and then SPLIT along it: corners computed on an
   !> incline and typed to four decimals miss the typed line by a few 1e-5,
   !> and with the tolerance alone the line crossed the block's own edges
   !> there, cutting slivers of no width (the block on the plane refused, or
   !> a column joined to a strip of zero width along the plane). Within this
   !> distance the cut runs through the corner, as a cut's end within the
   !> minimum edge of a corner moves onto it (locate_on_boundary).
   pure real(wp) function cut_line_tol(geo)
      type(geometry_t), intent(in) :: geo
      cut_line_tol = max(4.0_wp*geo%tol, 0.01_wp*geo%edge_min)
   end function cut_line_tol

   !> Which edge a point lies on (0: interior: farther than `near` from every
   !> edge); snaps to a corner closer than the minimum edge, otherwise
   !> projects onto the edge.
   subroutine locate_on_boundary(geo, x, y, px, py, edge, vert, s, moved, near)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(inout) :: px, py
      integer(ip), intent(out) :: edge, vert
      real(wp), intent(out) :: s
      logical, intent(out) :: moved
      real(wp), intent(in) :: near
      integer(ip) :: i, j, n
      real(wp) :: d, t, dbest, tbest, len, snap
      n = size(x)
      edge = 0
      vert = 0
      s = 0.0_wp
      moved = .false.
      dbest = huge(1.0_wp)
      tbest = 0.0_wp
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         call segment_distance(px, py, x(i), y(i), x(j), y(j), d, t)
         if (d < dbest) then
            dbest = d
            edge = i
            tbest = t
         end if
      end do
      if (dbest > near) then
         edge = 0
         return
      end if
      i = edge
      j = merge(1_ip, i + 1_ip, i == n)
      len = hypot(x(j) - x(i), y(j) - y(i))
      ! a point that would leave a piece of this edge shorter than the
      ! minimum edge moves onto the nearer corner (on an edge shorter than
      ! twice the minimum, every point does)
      snap = geo%edge_min - geo%tol
      if (tbest*len < snap .or. (1.0_wp - tbest)*len < snap) then
         if (tbest <= 0.5_wp) then
            vert = i
         else
            vert = j
         end if
      end if
      if (vert > 0) then
         moved = hypot(px - x(vert), py - y(vert)) > 4.0_wp*geo%tol
         px = x(vert)
         py = y(vert)
         s = merge(0.0_wp, 1.0_wp, vert == i)
      else
         px = x(i) + tbest*(x(j) - x(i))
         py = y(i) + tbest*(y(j) - y(i))
         s = tbest
      end if
   end subroutine locate_on_boundary

   !> Apply one straight cut to every block it meets (SPLIT or CRACK mode).
   subroutine cut_apply_segment(geo, ax, ay, bx, by, mode, out, merge_below)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: ax, ay, bx, by
      integer(ip), intent(in) :: mode
      type(output_t), intent(in), optional :: out
      real(wp), intent(in), optional :: merge_below(5)
      integer(ip), allocatable :: stack(:), touched(:)
      integer(ip) :: nstack, ntouched, b, i, np, newb, npass
      type(piece_t), allocatable :: pieces(:)
      real(wp), allocatable :: x(:), y(:)
      logical :: partial, done
      real(wp) :: px(2), py(2)
      if (hypot(bx - ax, by - ay) <= geo%tol) return
      call blocks_along(geo, ax, ay, bx, by, stack, nstack)
      allocate (touched(max(16_ip, 2*nstack)))
      ntouched = 0
      partial = .false.
      npass = 0
      do
         call pop_live_block(geo, stack, nstack, npass, b)
         if (b == 0) exit
         call geometry_block_polygon(geo, b, x, y)
         call block_pieces(geo, x, y, ax, ay, bx, by, pieces, np)
         done = .false.
         do i = 1, np
            associate (p => pieces(i))
               if (p%edge_a > 0 .and. p%edge_b > 0) then
                  px = [p%xa, p%xb]
                  py = [p%ya, p%yb]
                  call split_block_path(geo, b, x, y, px, py, p%edge_a, p%vert_a, p%s_a, &
                                        p%edge_b, p%vert_b, p%s_b, newb, out, &
                                        merge_slivers=.true., merge_below=merge_below)
                  if (newb > 0) then
                     if (p%moved_a) geo%cut_stats(cut_snapped) = geo%cut_stats(cut_snapped) + 1
                     if (p%moved_b) geo%cut_stats(cut_snapped) = geo%cut_stats(cut_snapped) + 1
                     call push_back(stack, nstack, b)
                     call push_back(stack, nstack, newb)
                     done = .true.
                     exit
                  end if
               else
                  partial = .true.
               end if
            end associate
         end do
         if (np > 0 .and. .not. done) call push_back(touched, ntouched, b)
      end do
      if (mode /= mode_crack) return
      if (partial) then
         call geometry_add_pending(geo, ax, ay, bx, by)
      end if
      if (geo%pending%n > 0) call complete_pending(geo, touched, ntouched, out, merge_below)
   end subroutine cut_apply_segment

   !> The next live block b of a cut's work stack (1..nstack), 0 when the
   !> stack is empty or after 20 (blocks + 100) pops (`npass` counts them):
   !> each pass splits a block, merges a sliver or finds nothing to cut, so
   !> the bound only guards against a cycle of sliver merges.
   subroutine pop_live_block(geo, stack, nstack, npass, b)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: stack(:)
      integer(ip), intent(inout) :: nstack, npass
      integer(ip), intent(out) :: b
      do while (nstack > 0)
         npass = npass + 1
         if (npass > 20*(geo%blocks%n + 100)) exit
         b = stack(nstack)
         nstack = nstack - 1
         if (geo%blocks%live(b)) return
      end do
      b = 0
   end subroutine pop_live_block

   !> Split blocks in which pending crack pieces now form a boundary-to-
   !> boundary chain; children are examined again.
   subroutine complete_pending(geo, stack, nstack, out, merge_below)
      type(geometry_t), intent(inout) :: geo
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: nstack
      type(output_t), intent(in), optional :: out
      real(wp), intent(in), optional :: merge_below(5)
      integer(ip), parameter :: max_attempts = 8
      integer(ip) :: b, newb, ea, va, eb, vb, attempt, npass
      real(wp), allocatable :: x(:), y(:), px(:), py(:)
      real(wp) :: sa, sb
      logical :: found
      npass = 0
      do
         call pop_live_block(geo, stack, nstack, npass, b)
         if (b == 0) exit
         call geometry_block_polygon(geo, b, x, y)
         ! a refused chain (short edge, sliver) must not hide the others
         do attempt = 0, max_attempts - 1
            call find_pending_path(geo, b, x, y, attempt, px, py, ea, va, sa, eb, vb, sb, &
                                   found)
            if (.not. found) exit
            call split_block_path(geo, b, x, y, px, py, ea, va, sa, eb, vb, sb, newb, out, &
                                  merge_slivers=.true., retry=.true., merge_below=merge_below)
            if (newb > 0) then
               call push_back(stack, nstack, b)
               call push_back(stack, nstack, newb)
               exit
            end if
         end do
      end do
   end subroutine complete_pending

   !> Search the pending crack pieces inside block b for a chain from one
   !> boundary point to another (breadth-first over the crack graph); the
   !> first `skip` chains found are passed over. With `loop` present and no
   !> chain found: a closed loop of pending pieces lying inside the block
   !> (touching no edge of it) that holds a piece of a pending segment
   !> numbered above `newfrom` gives [xr, yr, xl, yl, w]: its rightmost and
   !> leftmost points and half its width (w = 0: no such loop).
   subroutine find_pending_path(geo, b, x, y, skip, px, py, ea, va, sa, eb, vb, sb, found, &
                                newfrom, loop)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b, skip
      real(wp), intent(in) :: x(:), y(:)
      real(wp), allocatable, intent(out) :: px(:), py(:)
      integer(ip), intent(out) :: ea, va, eb, vb
      real(wp), intent(out) :: sa, sb
      logical, intent(out) :: found
      integer(ip), intent(in), optional :: newfrom
      real(wp), intent(out), optional :: loop(5)
      type(piece_t), allocatable :: all(:), pieces(:), tmp(:)
      integer(ip) :: na, np, i, j, k, c, p, q, id, nn, ne, nh, maxn, nslot, start, cur, head, &
                     tail, nfound
      real(wp), allocatable :: nx(:), ny(:), prm(:), lo(:), hs(:), ht(:)
      integer(ip), allocatable :: nedge(:), nvert(:), eu(:), ev(:), ids(:), parent(:), queue(:), &
                                  src(:), epend(:)
      integer(ip), allocatable :: cnt(:), off(:), order(:), hp(:), hq(:), hord(:), nnext(:), &
                                  deg(:), adj(:), fill(:), shead(:)
      integer(i8), allocatable :: skx(:), sky(:)
      real(wp), allocatable :: ns(:)
      real(wp) :: s, t, margin, xhi, cell
      logical :: hit
      found = .false.
      ea = 0; eb = 0; va = 0; vb = 0; sa = 0.0_wp; sb = 0.0_wp
      if (present(loop)) loop = 0.0_wp
      allocate (all(8), src(8))
      na = 0
      do i = 1, geo%pending%n
         associate (x1 => geo%pending%x1(i), y1 => geo%pending%y1(i), &
                    x2 => geo%pending%x2(i), y2 => geo%pending%y2(i))
            if (max(x1, x2) < geo%blocks%xmin(b) - geo%tol) cycle
            if (min(x1, x2) > geo%blocks%xmax(b) + geo%tol) cycle
            if (max(y1, y2) < geo%blocks%ymin(b) - geo%tol) cycle
            if (min(y1, y2) > geo%blocks%ymax(b) + geo%tol) cycle
            call block_pieces(geo, x, y, x1, y1, x2, y2, pieces, np)
         end associate
         do j = 1, np
            if (na >= size(all)) then
               allocate (tmp(2*size(all)))
               tmp(1:na) = all(1:na)
               call move_alloc(tmp, all)
               call grow_lists(na, 2_ip*size(src, kind=ip), src)
            end if
            na = na + 1
            all(na) = pieces(j)
            src(na) = i
         end do
      end do
      if (na == 0) return
      ! a single piece crossing the block (the block was split since) is a chord
      nfound = 0
      do i = 1, na
         if (all(i)%edge_a > 0 .and. all(i)%edge_b > 0) then
            nfound = nfound + 1
            if (nfound <= skip) cycle
            px = [all(i)%xa, all(i)%xb]
            py = [all(i)%ya, all(i)%yb]
            ea = all(i)%edge_a; va = all(i)%vert_a; sa = all(i)%s_a
            eb = all(i)%edge_b; vb = all(i)%vert_b; sb = all(i)%s_b
            found = .true.
            return
         end if
      end do
      if (na < 2) return
      ! Crossings: a sweep along x (pieces by their left ends) tests only pieces
      ! whose boxes overlap, and the pairs found are then taken in (i, j) order,
      ! the order of a test of every pair: node numbers and the order of a
      ! piece's entries do not depend on the sweep. A test of every pair, node
      ! merging by a scan of every node and a breadth-first search scanning
      ! every graph edge made this search grow with the fourth power and more
      ! of the pieces in a block: a JSET of short joints kept pending in one
      ! block (990 of them) took 6 s, and refused chains tried again took minutes.
      allocate (lo(na), order(na))
      do i = 1, na
         lo(i) = min(all(i)%xa, all(i)%xb)
      end do
      call sort_order(lo, order)
      margin = geo%tol
      nh = 0
      allocate (hp(16), hq(16), hs(16), ht(16))
      do k = 1, na
         i = order(k)
         xhi = max(all(i)%xa, all(i)%xb) + margin
         do c = k + 1, na
            j = order(c)
            if (lo(j) > xhi) exit
            if (min(all(j)%ya, all(j)%yb) > max(all(i)%ya, all(i)%yb) + margin) cycle
            if (max(all(j)%ya, all(j)%yb) < min(all(i)%ya, all(i)%yb) - margin) cycle
            p = min(i, j)
            q = max(i, j)
            call segment_intersection(all(p)%xa, all(p)%ya, all(p)%xb, all(p)%yb, &
                                      all(q)%xa, all(q)%ya, all(q)%xb, all(q)%yb, hit, s, t)
            if (.not. hit) cycle
            if (nh >= size(hp)) call grow_hits()
            nh = nh + 1
            hp(nh) = p; hq(nh) = q; hs(nh) = s; ht(nh) = t
         end do
      end do
      allocate (hord(nh))
      call sort_order_pairs(hp(1:nh), hq(1:nh), hord)
      ! nodes: piece ends and crossings, merged within tolerance
      maxn = 2*na + nh
      allocate (nx(maxn), ny(maxn), nedge(maxn), nvert(maxn), ns(maxn), nnext(maxn))
      nn = 0
      call hash_init(maxn)
      ! each piece's entries (parameter, node): ends, then crossings
      allocate (cnt(na), off(na + 1))
      cnt = 2
      do k = 1, nh
         cnt(hp(k)) = cnt(hp(k)) + 1
         cnt(hq(k)) = cnt(hq(k)) + 1
      end do
      off(1) = 0
      do i = 1, na
         off(i + 1) = off(i) + cnt(i)
      end do
      allocate (prm(off(na + 1)), ids(off(na + 1)))
      cnt = 0
      do i = 1, na
         call add_node(all(i)%xa, all(i)%ya, all(i)%edge_a, all(i)%vert_a, all(i)%s_a, id)
         call add_entry(i, 0.0_wp, id)
         call add_node(all(i)%xb, all(i)%yb, all(i)%edge_b, all(i)%vert_b, all(i)%s_b, id)
         call add_entry(i, 1.0_wp, id)
      end do
      do c = 1, nh
         k = hord(c)
         p = hp(k)
         call add_node(all(p)%xa + hs(k)*(all(p)%xb - all(p)%xa), &
                       all(p)%ya + hs(k)*(all(p)%yb - all(p)%ya), 0_ip, 0_ip, 0.0_wp, id)
         call add_entry(p, hs(k), id)
         call add_entry(hq(k), ht(k), id)
      end do
      ! graph edges between consecutive nodes along each piece
      allocate (eu(off(na + 1)), ev(off(na + 1)), epend(off(na + 1)))
      ne = 0
      do i = 1, na
         call sort_entries(i, cnt(i))
         do j = off(i) + 1, off(i) + cnt(i) - 1
            if (ids(j) == ids(j + 1)) cycle
            ne = ne + 1
            eu(ne) = ids(j)
            ev(ne) = ids(j + 1)
            epend(ne) = src(i)
         end do
      end do
      ! each node's neighbours, in the order of the edges
      allocate (deg(nn + 1), adj(2*ne), fill(nn))
      deg = 0
      do k = 1, ne
         deg(eu(k) + 1) = deg(eu(k) + 1) + 1
         deg(ev(k) + 1) = deg(ev(k) + 1) + 1
      end do
      deg(1) = 0
      do i = 2, nn + 1
         deg(i) = deg(i) + deg(i - 1)
      end do
      fill = deg(1:nn)
      do k = 1, ne
         fill(eu(k)) = fill(eu(k)) + 1
         adj(fill(eu(k))) = ev(k)
         fill(ev(k)) = fill(ev(k)) + 1
         adj(fill(ev(k))) = eu(k)
      end do
      ! breadth-first search from each boundary node
      allocate (parent(nn), queue(nn))
      do start = 1, nn
         if (nedge(start) == 0) cycle
         parent = 0
         parent(start) = start
         head = 1
         tail = 1
         queue(1) = start
         do while (head <= tail)
            cur = queue(head)
            head = head + 1
            if (cur /= start .and. nedge(cur) > 0) then
               if (hypot(nx(cur) - nx(start), ny(cur) - ny(start)) > geo%tol) then
                  nfound = nfound + 1
                  if (nfound <= skip) exit
                  call build_path(start, cur)
                  found = .true.
                  return
               end if
               cycle     ! a boundary node ends a chain
            end if
            do k = deg(cur) + 1, deg(cur + 1)
               j = adj(k)
               if (parent(j) /= 0) cycle
               parent(j) = cur
               tail = tail + 1
               queue(tail) = j
            end do
         end do
      end do
      if (present(loop) .and. present(newfrom)) call closed_loop()
   contains
      !> The loops of the crack graph are its 2-core (what is left once
      !> every node of one neighbour has been taken away, again and again);
      !> the first part of it that touches no edge of the block and holds a
      !> piece of a new segment gives `loop`.
      subroutine closed_loop()
         integer(ip), allocatable :: d(:), comp(:)
         logical, allocatable :: fresh(:)
         integer(ip) :: v, w, h, t, ir, il
         logical :: onedge, isnew
         allocate (d(nn), fresh(nn), comp(nn))
         fresh = .false.
         do k = 1, ne
            if (epend(k) <= newfrom) cycle
            fresh(eu(k)) = .true.
            fresh(ev(k)) = .true.
         end do
         d = deg(2:nn + 1) - deg(1:nn)
         ! prune the nodes of one neighbour (queue reused)
         t = 0
         do v = 1, nn
            if (d(v) <= 1) then
               t = t + 1
               queue(t) = v
            end if
         end do
         h = 1
         do while (h <= t)
            v = queue(h)
            h = h + 1
            d(v) = -1
            do k = deg(v) + 1, deg(v + 1)
               w = adj(k)
               if (d(w) < 0) cycle
               d(w) = d(w) - 1
               if (d(w) == 1) then
                  t = t + 1
                  queue(t) = w
               end if
            end do
         end do
         comp = 0
         do start = 1, nn
            if (d(start) < 2 .or. comp(start) /= 0) cycle
            ! one connected part of the 2-core
            comp(start) = start
            t = 1
            queue(1) = start
            h = 1
            onedge = .false.
            isnew = .false.
            ir = start
            il = start
            do while (h <= t)
               v = queue(h)
               h = h + 1
               onedge = onedge .or. nedge(v) > 0
               isnew = isnew .or. fresh(v)
               if (nx(v) > nx(ir)) ir = v
               if (nx(v) < nx(il)) il = v
               do k = deg(v) + 1, deg(v + 1)
                  w = adj(k)
                  if (d(w) < 2 .or. comp(w) /= 0) cycle
                  comp(w) = start
                  t = t + 1
                  queue(t) = w
               end do
            end do
            if (onedge .or. .not. isnew .or. .not. nx(ir) - nx(il) > 4.0_wp*geo%tol) cycle
            ! pieces drawn twice along one line close no loop: some node
            ! must lie off the line between the two ends
            if (.not. any(abs((nx(queue(1:t)) - nx(il))*(ny(ir) - ny(il)) - &
                              (ny(queue(1:t)) - ny(il))*(nx(ir) - nx(il))) > &
                          4.0_wp*geo%tol*hypot(nx(ir) - nx(il), ny(ir) - ny(il)))) cycle
            loop = [nx(ir), ny(ir), nx(il), ny(il), 0.5_wp*(nx(ir) - nx(il))]
            return
         end do
      end subroutine closed_loop
      !> Twice the room for the hits (hp, hq, hs, ht share a capacity).
      subroutine grow_hits()
         integer(ip) :: m
         m = 2_ip*size(hp, kind=ip)
         call grow_lists(nh, m, hp, hq)
         call grow_lists(nh, m, hs, ht)
      end subroutine grow_hits
      !> Hash of square cells a little wider than the merge distance 4 tol:
      !> a node within that distance of a point is in its cell or a neighbour.
      subroutine hash_init(n)
         integer(ip), intent(in) :: n
         nslot = 64
         do while (nslot < 4*n)
            nslot = 2*nslot
         end do
         allocate (skx(0:nslot - 1), sky(0:nslot - 1), shead(0:nslot - 1))
         shead = -1
         cell = 1.001_wp*4.0_wp*geo%tol
         if (.not. cell > 0.0_wp) cell = 1.0_wp
      end subroutine hash_init
      integer(i8) function cell_of(v)
         real(wp), intent(in) :: v
         cell_of = floor(max(-4.0e18_wp, min(4.0e18_wp, v/cell)), i8)
      end function cell_of
      !> Slot of cell (cx, cy): its own, or the empty one where it would go.
      integer(ip) function slot_of(cx, cy)
         integer(i8), intent(in) :: cx, cy
         integer(i8) :: hsh
         ! the low 31 bits of each, so the products cannot overflow
         hsh = ieor(iand(cx, 2147483647_i8)*73856093_i8, iand(cy, 2147483647_i8)*19349663_i8)
         slot_of = int(iand(hsh, int(nslot - 1, i8)), ip)
         do while (shead(slot_of) >= 0)
            if (skx(slot_of) == cx .and. sky(slot_of) == cy) return
            slot_of = iand(slot_of + 1_ip, nslot - 1_ip)
         end do
      end function slot_of
      !> The node of lowest number within 4 tol of (xp, yp) (as a scan of
      !> every node in order would find), or a new node there.
      subroutine add_node(xp, yp, e, v, sp, id)
         real(wp), intent(in) :: xp, yp, sp
         integer(ip), intent(in) :: e, v
         integer(ip), intent(out) :: id
         integer(ip) :: q, sl, best, dx, dy
         integer(i8) :: cx, cy
         cx = cell_of(xp)
         cy = cell_of(yp)
         best = 0
         do dx = -1, 1
            do dy = -1, 1
               sl = slot_of(cx + dx, cy + dy)
               q = max(shead(sl), 0_ip)
               do while (q > 0)
                  if (hypot(nx(q) - xp, ny(q) - yp) <= 4.0_wp*geo%tol) then
                     if (best == 0 .or. q < best) best = q
                  end if
                  q = nnext(q)
               end do
            end do
         end do
         if (best > 0) then
            id = best
            if (nedge(best) == 0 .and. e > 0) then
               nedge(best) = e; nvert(best) = v; ns(best) = sp
            end if
            return
         end if
         nn = nn + 1
         nx(nn) = xp; ny(nn) = yp; nedge(nn) = e; nvert(nn) = v; ns(nn) = sp
         id = nn
         sl = slot_of(cx, cy)
         if (shead(sl) < 0) then
            skx(sl) = cx
            sky(sl) = cy
            shead(sl) = 0
         end if
         nnext(nn) = shead(sl)
         shead(sl) = nn
      end subroutine add_node
      subroutine add_entry(ip_, t_, id)
         integer(ip), intent(in) :: ip_, id
         real(wp), intent(in) :: t_
         cnt(ip_) = cnt(ip_) + 1
         prm(off(ip_) + cnt(ip_)) = t_
         ids(off(ip_) + cnt(ip_)) = id
      end subroutine add_entry
      subroutine sort_entries(ip_, c)
         integer(ip), intent(in) :: ip_, c
         integer(ip) :: o, order(c)
         o = off(ip_)
         call sort_order(prm(o + 1:o + c), order)
         prm(o + 1:o + c) = prm(o + order)
         ids(o + 1:o + c) = ids(o + order)
      end subroutine sort_entries
      subroutine build_path(first, last)
         integer(ip), intent(in) :: first, last
         integer(ip) :: q, len
         len = 1
         q = last
         do while (q /= first)
            q = parent(q)
            len = len + 1
         end do
         allocate (px(len), py(len))
         q = last
         do j = len, 1, -1
            px(j) = nx(q)
            py(j) = ny(q)
            if (j > 1) q = parent(q)
         end do
         ea = nedge(first); va = nvert(first); sa = ns(first)
         eb = nedge(last); vb = nvert(last); sb = ns(last)
      end subroutine build_path
   end subroutine find_pending_path

   !> Split block b along the path px,py whose ends lie on edges ea, eb
   !> (corner va/vb when snapped, parameter sa/sb along the edge) and whose
   !> interior points are inside. newb = id of the second block, or 0 when
   !> the split is refused.
   subroutine split_block_path(geo, b, x, y, path_x, path_y, ea, va, sa, eb, vb, sb, newb, out, &
                               merge_slivers, retry, merge_below)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in), optional :: merge_slivers, retry
      real(wp), intent(in), optional :: merge_below(5)
      integer(ip), intent(in) :: b, ea, va, eb, vb
      real(wp), intent(in) :: x(:), y(:), path_x(:), path_y(:), sa, sb
      integer(ip), intent(out) :: newb
      type(output_t), intent(in), optional :: out
      real(wp), allocatable :: qx(:), qy(:)
      real(wp) :: ta_s, tb_s, sa_t, sb_t
      integer(ip) :: np, ta, tb, da, db, va_t, vb_t
      ! A cut end on an edge whose nearer corner on the cut's acute side
      ! lies within the minimum edge of the cut's line (a tooth of the
      ! block, thinner than EDGE there, between the cut and that edge)
      ! moves onto that corner, when the cut made so is valid as it is.
      ! Not for a TUNNEL ring's cuts (merge_below): its corners are snapped
      ! onto the joints they graze before it is cut (cut_snapped_ring), and
      ! a side's end moved here along a joint left the ring crossing blocks
      ! (stability.tunnel_2_sets_sets-first).
      np = size(path_x)
      ta = 0
      tb = 0
      if (present(merge_below)) then
         call split_block_path_as(geo, b, x, y, path_x, path_y, ea, va, sa, eb, vb, sb, newb, &
                                  out, merge_slivers, retry, merge_below)
         return
      end if
      if (va == 0 .and. ea > 0) call tooth_corner(geo, x, y, ea, sa, path_x, path_y, ta, ta_s, da)
      if (vb == 0 .and. eb > 0) call tooth_corner(geo, x, y, eb, sb, path_x(np:1:-1), &
                                                  path_y(np:1:-1), tb, tb_s, db)
      if (ta > 0 .and. tb > 0 .and. da + db > np - 2) tb = 0
      if (ta > 0 .or. tb > 0) then
         if (ta == 0) da = 0
         if (tb == 0) db = 0
         ! the path's points behind the corner's foot go
         qx = [path_x(1), path_x(2 + da:np - 1 - db), path_x(np)]
         qy = [path_y(1), path_y(2 + da:np - 1 - db), path_y(np)]
         if (ta > 0) then
            qx(1) = x(ta)
            qy(1) = y(ta)
         end if
         if (tb > 0) then
            qx(size(qx)) = x(tb)
            qy(size(qy)) = y(tb)
         end if
         ! the ends as moved: a corner (its parameter on the edge) or as given
         va_t = merge(ta, va, ta > 0)
         sa_t = merge(ta_s, sa, ta > 0)
         vb_t = merge(tb, vb, tb > 0)
         sb_t = merge(tb_s, sb, tb > 0)
         call split_block_path_as(geo, b, x, y, qx, qy, ea, va_t, sa_t, eb, vb_t, sb_t, newb, &
                                  out, merge_slivers, retry, merge_below, dry=.true.)
         ! -1: the cut is made so; -2: it runs along an existing edge (the
         ! joint is there already, within EDGE: what is left of the cut
         ! would cut the thin wedge between them off), nothing to cut
         if (newb == -2) then
            geo%cut_stats(cut_touch) = geo%cut_stats(cut_touch) + 1
            newb = 0
            return
         else if (newb == -1) then
            call split_block_path_as(geo, b, x, y, qx, qy, ea, va_t, sa_t, eb, vb_t, sb_t, &
                                     newb, out, merge_slivers, retry, merge_below)
            ! counted with the cut ends moved onto corners
            if (newb > 0) geo%cut_stats(cut_snapped) = geo%cut_stats(cut_snapped) + &
                                                     count([ta, tb] > 0)
            return
         end if
      end if
      call split_block_path_as(geo, b, x, y, path_x, path_y, ea, va, sa, eb, vb, sb, newb, out, &
                               merge_slivers, retry, merge_below)
   end subroutine split_block_path

   !> The corner v of edge e (polygon x, y) that the end (px(1), py(1)) of a
   !> cut's path, at parameter s along e, should move onto, or 0: the
   !> corner on the side where the path's first step meets the edge at an
   !> acute angle, when it lies within the minimum edge of that step's line
   !> and its foot on the line lies inside the path. The piece of the block
   !> between the cut and the edge there, a tooth, would be thinner than
   !> EDGE at that corner: l3's JSET left one of 6.5 degrees, 0.33 m long
   !> and 0.038 m wide (ROUND 0.1, EDGE 0.2), whose zones of 2.3e-4 m2 set
   !> the step of the whole model. `sv` is the corner's parameter on e (0 or
   !> 1); `ndrop` counts the path's inner points up to the foot (within
   !> EDGE of the line), which the moved path leaves out.
   subroutine tooth_corner(geo, x, y, e, s, px, py, v, sv, ndrop)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x(:), y(:), s, px(:), py(:)
      integer(ip), intent(in) :: e
      integer(ip), intent(out) :: v, ndrop
      real(wp), intent(out) :: sv
      integer(ip) :: j, k, n
      real(wp) :: ex, ey, ux, uy, lu, along, h, t
      v = 0
      sv = 0.0_wp
      ndrop = 0
      n = size(px)
      j = merge(1_ip, e + 1_ip, e == size(x))
      ex = x(j) - x(e)
      ey = y(j) - y(e)
      ux = px(2) - px(1)
      uy = py(2) - py(1)
      lu = hypot(ux, uy)
      if (lu <= geo%tol .or. hypot(ex, ey) <= geo%tol) return
      ux = ux/lu
      uy = uy/lu
      if (ux*ex + uy*ey > 0.0_wp) then
         v = j
         sv = 1.0_wp
      else
         v = e
      end if
      if (abs(sv - s)*hypot(ex, ey) <= 4.0_wp*geo%tol) then
         v = 0
         return
      end if
      along = (x(v) - px(1))*ux + (y(v) - py(1))*uy
      h = abs((x(v) - px(1))*uy - (y(v) - py(1))*ux)
      if (.not. (h < geo%edge_min - geo%tol .and. along > 0.0_wp)) then
         v = 0
         return
      end if
      ! the path's points up to the foot: dropped when near the line
      do k = 2, n
         t = (px(k) - px(1))*ux + (py(k) - py(1))*uy
         if (t > along) return
         if (k == n .or. abs((px(k) - px(1))*uy - (py(k) - py(1))*ux) >= geo%edge_min) exit
         ndrop = ndrop + 1
      end do
      v = 0
   end subroutine tooth_corner

   !> split_block_path with the ends as given; with `dry` present nothing
   !> changes and newb is -1 when the cut would be made as it is (no piece a
   !> sliver), 0 when it would be refused.
   subroutine split_block_path_as(geo, b, x, y, path_x, path_y, ea, va, sa, eb, vb, sb, newb, &
                                  out, merge_slivers, retry, merge_below, dry)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in), optional :: dry
      !> a sliver left by this cut may be merged into a neighbour (else it
      !> is refused)
      logical, intent(in), optional :: merge_slivers
      !> a pending chain tried again after a later crack: a chain found to run
      !> along an existing edge is counted but not noted (it is found again
      !> with every crack that touches the block: 450 notes for one block)
      logical, intent(in), optional :: retry
      !> TUNNEL's ring [area, xc, yc, r, n]: a piece outside the ring smaller
      !> than area, the other not, is merged into a neighbour where it can
      !> be, like a sliver; else the cut is made as it is
      real(wp), intent(in), optional :: merge_below(5)
      integer(ip), intent(in) :: b, ea, va, eb, vb
      real(wp), intent(in) :: x(:), y(:), path_x(:), path_y(:), sa, sb
      integer(ip), intent(out) :: newb
      type(output_t), intent(in), optional :: out
      real(wp), allocatable :: wx(:), wy(:), x1(:), y1(:), x2(:), y2(:), px(:), py(:)
      integer(ip) :: n, np, nw, k, ia, ib, n1, n2, i
      logical :: first_a, ok, snapped, thin1, thin2
      real(wp) :: a1, a2
      integer(ip) :: nbend
      character(len=120) :: text
      newb = 0
      n = size(x)
      ! A bend of the path (a tunnel ring's corner, the meeting point of two
      ! crack pieces) closer than the minimum edge to the previous point or
      ! to the path's end is moved onto that point: the path straightens
      ! there instead of the whole cut being refused for a short new edge.
      np = size(path_x)
      nbend = 0
      allocate (px(np), py(np))
      px(1) = path_x(1)
      py(1) = path_y(1)
      k = 1
      do i = 2, np - 1
         if (hypot(path_x(i) - px(k), path_y(i) - py(k)) < geo%edge_min - geo%tol) cycle
         if (hypot(path_x(i) - path_x(np), path_y(i) - path_y(np)) < geo%edge_min - geo%tol) cycle
         k = k + 1
         px(k) = path_x(i)
         py(k) = path_y(i)
      end do
      k = k + 1
      px(k) = path_x(np)
      py(k) = path_y(np)
      if (k < np) then
         ! counted when the cut is made (a refused chain is found again)
         nbend = np - k
         px = px(1:k)
         py = py(1:k)
      end if
      np = k
      allocate (wx(n + 2), wy(n + 2))
      nw = 0
      ia = 0
      ib = 0
      ! same edge: insert in order along it
      first_a = .true.
      if (va == 0 .and. vb == 0 .and. ea == eb) first_a = sa <= sb
      do k = 1, n
         nw = nw + 1
         wx(nw) = x(k)
         wy(nw) = y(k)
         if (va == k) ia = nw
         if (vb == k) ib = nw
         if (first_a) then
            call insert_a()
            call insert_b()
         else
            call insert_b()
            call insert_a()
         end if
      end do
      if (ia == ib .or. ia == 0 .or. ib == 0) then
         call refuse('cut ends at one point', cut_touch)
         return
      end if
      ! piece 1: boundary a -> b, then path back b -> a
      n1 = modulo(ib - ia, nw) + 1 + (np - 2)
      n2 = modulo(ia - ib, nw) + 1 + (np - 2)
      allocate (x1(n1), y1(n1), x2(n2), y2(n2))
      do i = 0, modulo(ib - ia, nw)
         x1(i + 1) = wx(modulo(ia - 1 + i, nw) + 1)
         y1(i + 1) = wy(modulo(ia - 1 + i, nw) + 1)
      end do
      k = modulo(ib - ia, nw) + 1
      do i = np - 1, 2, -1
         k = k + 1
         x1(k) = px(i)
         y1(k) = py(i)
      end do
      do i = 0, modulo(ia - ib, nw)
         x2(i + 1) = wx(modulo(ib - 1 + i, nw) + 1)
         y2(i + 1) = wy(modulo(ib - 1 + i, nw) + 1)
      end do
      k = modulo(ia - ib, nw) + 1
      do i = 2, np - 1
         k = k + 1
         x2(k) = px(i)
         y2(k) = py(i)
      end do
      if (n1 < 3 .or. n2 < 3) then
         call refuse('cut runs along an existing edge', cut_touch)
         return
      end if
      ! a path of several steps lying along the block's boundary leaves a
      ! piece of no area: nothing to cut
      if (-polygon_signed_area(x1, y1) <= 4.0_wp*geo%tol*geo%extent .or. &
          -polygon_signed_area(x2, y2) <= 4.0_wp*geo%tol*geo%extent) then
         call refuse('cut runs along an existing edge', cut_touch)
         return
      end if
      ! new edges: the path and the pieces of the cut edges
      do i = 1, np - 1
         if (hypot(px(i + 1) - px(i), py(i + 1) - py(i)) < geo%edge_min - geo%tol) then
            call refuse('new edge shorter than the minimum edge', cut_refused_short)
            return
         end if
      end do
      call check_piece(x1, y1, ok, thin1)
      if (ok) call check_piece(x2, y2, ok, thin2)
      if (.not. ok) return
      if (thin1 .and. thin2) then
         call refuse('both pieces would be slivers', cut_refused_sliver)
         return
      end if
      if (thin1 .or. thin2) then
         ok = .false.
         if (present(merge_slivers)) ok = merge_slivers
         if (.not. ok) then
            call refuse('piece would be a sliver or smaller than the minimum area', &
                        cut_refused_sliver)
            return
         end if
      end if
      snapped = va > 0 .or. vb > 0
      if (snapped .or. np > 2) then
         if (.not. polygon_is_simple(x1, y1, geo%tol) .or. &
             .not. polygon_is_simple(x2, y2, geo%tol)) then
            call refuse('pieces would not be simple polygons', cut_refused_shape)
            return
         end if
      end if
      if (present(dry)) then
         if (.not. (thin1 .or. thin2)) newb = -1
         return
      end if
      ! a sliver joins a neighbour; block b changed, so newb = b sends it
      ! back to the caller's stack to be cut again from its new polygon
      if (thin1 .or. thin2) then
         call absorb_piece(thin1)
         if (ok) then
            newb = b
            geo%cut_stats(cut_bend_moved) = geo%cut_stats(cut_bend_moved) + nbend
         else
            call refuse('piece would be a sliver that cannot be merged', cut_refused_sliver)
         end if
         return
      end if
      ! a small piece (a TUNNEL ring cutting a block's tip off) joins a
      ! neighbour where it can; where it cannot, the cut is made
      if (present(merge_below)) then
         a1 = -polygon_signed_area(x1, y1)
         a2 = -polygon_signed_area(x2, y2)
         if (min(a1, a2) < merge_below(1) .and. max(a1, a2) >= merge_below(1) .and. &
             outside_ring(a1 < a2)) then
            call absorb_piece(a1 < a2)
            if (ok) then
               newb = b
               geo%cut_stats(cut_bend_moved) = geo%cut_stats(cut_bend_moved) + nbend
               return
            end if
         end if
      end if
      geo%cut_stats(cut_made) = geo%cut_stats(cut_made) + 1
      geo%cut_stats(cut_bend_moved) = geo%cut_stats(cut_bend_moved) + nbend
      call geometry_set_block_polygon(geo, b, x1, y1)
      ! material and cons by value: the block list may be reallocated while
      ! the new block is added
      call geometry_add_block(geo, x2, y2, (geo%blocks%material(b)), (geo%blocks%cons(b)), newb)
      ! 1989 addresses of the new block and the corners the cut made (model_address)
      call address_split(geo, b, newb, px(1), py(1), va == 0, x(max(ea, 1_ip)), y(max(ea, 1_ip)), &
                         px(np), py(np), vb == 0, x(max(eb, 1_ip)), y(max(eb, 1_ip)))
   contains
      !> Merge piece 1 (first) or piece 2 into a neighbour; `ok` says whether
      !> it was (absorb_sliver).
      subroutine absorb_piece(first)
         logical, intent(in) :: first
         if (first) then
            call absorb_sliver(geo, b, x1, y1, x2, y2, px, py, ok, present(merge_below))
         else
            call absorb_sliver(geo, b, x2, y2, x1, y1, px, py, ok, present(merge_below))
         end if
      end subroutine absorb_piece
      !> Whether piece 1 (first) or 2 lies outside the ring merge_below(2:5)
      !> (its centroid beyond the line of a side): a piece inside goes with
      !> the opening and needs no merge (merged outward, it took 1.6 % off
      !> the opening of examples.geometry_scenes).
      logical function outside_ring(first)
         logical, intent(in) :: first
         real(wp) :: cx, cy, ca, th
         integer(ip) :: q, nside
         if (first) then
            call polygon_centroid(x1, y1, cx, cy, ca)
         else
            call polygon_centroid(x2, y2, cx, cy, ca)
         end if
         nside = nint(merge_below(5), ip)
         outside_ring = .false.
         do q = 1, nside
            ! the normal of the side between corners q and q + 1 (clockwise
            ! from angle 0, ring_polygon)
            th = -pi*real(2*q - 1, wp)/real(nside, wp)
            if ((cx - merge_below(2))*cos(th) + (cy - merge_below(3))*sin(th) > &
                merge_below(4)*cos(pi/real(nside, wp))) then
               outside_ring = .true.
               return
            end if
         end do
      end function outside_ring
      subroutine insert_a()
         if (va == 0 .and. ea == k) then
            nw = nw + 1
            wx(nw) = px(1)
            wy(nw) = py(1)
            ia = nw
         end if
      end subroutine insert_a
      subroutine insert_b()
         if (vb == 0 .and. eb == k) then
            nw = nw + 1
            wx(nw) = px(np)
            wy(nw) = py(np)
            ib = nw
         end if
      end subroutine insert_b
      subroutine check_piece(cx, cy, good, thin)
         real(wp), intent(in) :: cx(:), cy(:)
         logical, intent(out) :: good, thin
         real(wp) :: area, perim
         integer(ip) :: q, q2
         area = -polygon_signed_area(cx, cy)
         perim = 0.0_wp
         good = .true.
         thin = .false.
         do q = 1, size(cx)
            q2 = merge(1_ip, q + 1_ip, q == size(cx))
            perim = perim + hypot(cx(q2) - cx(q), cy(q2) - cy(q))
            ! an edge next to an inserted cut point is new and must not be short
            if ((va == 0 .and. (is_pt(cx(q), cy(q), px(1), py(1)) .or. &
                                is_pt(cx(q2), cy(q2), px(1), py(1)))) .or. &
                (vb == 0 .and. (is_pt(cx(q), cy(q), px(np), py(np)) .or. &
                                is_pt(cx(q2), cy(q2), px(np), py(np))))) then
               if (hypot(cx(q2) - cx(q), cy(q2) - cy(q)) < geo%edge_min - geo%tol) then
                  call refuse('new edge shorter than the minimum edge', cut_refused_short)
                  good = .false.
                  return
               end if
            end if
         end do
         ! 2 A / P bounds a convex block's inscribed radius from above: a
         ! piece thinner than the rounding length cannot hold its corner
         ! circles, so it is a sliver
         thin = area < 0.1_wp*geo%edge_min**2 .or. 2.0_wp*area < geo%round*perim
      end subroutine check_piece
      pure logical function is_pt(ax_, ay_, bx_, by_)
         real(wp), intent(in) :: ax_, ay_, bx_, by_
         is_pt = ax_ == bx_ .and. ay_ == by_
      end function is_pt
      subroutine refuse(why, kind)
         character(len=*), intent(in) :: why
         integer(ip), intent(in) :: kind
         if (present(dry)) then
            if (kind == cut_touch) newb = -2
            return
         end if
         ! a refused chain found again (the same block, path ends and
         ! reason) is neither counted nor noted again
         if (kind /= cut_touch) then
            if (refused_before(real(kind, wp))) return
         end if
         geo%cut_stats(kind) = geo%cut_stats(kind) + 1
         if (kind == cut_touch .and. present(retry)) then
            if (retry) return
         end if
         if (present(out)) then
            if (.not. out%detail) return
            write (text, '(a,i0,a)') 'Note: cut in block ', b, ' refused: '//why
            call out%line(trim(text))
         end if
      end subroutine refuse
      logical function refused_before(kind)
         real(wp), intent(in) :: kind
         real(wp) :: key(6)
         real(wp), allocatable :: grown(:, :)
         integer(ip) :: q
         ! the path's ends in either order
         if (px(1) < px(np) .or. (px(1) == px(np) .and. py(1) <= py(np))) then
            key = [real(b, wp), kind, px(1), py(1), px(np), py(np)]
         else
            key = [real(b, wp), kind, px(np), py(np), px(1), py(1)]
         end if
         refused_before = .true.
         do q = 1, geo%nrefused_keys
            if (all(abs(geo%refused_keys(:, q) - key) <= [0.0_wp, 0.0_wp, &
                    4.0_wp*geo%tol, 4.0_wp*geo%tol, 4.0_wp*geo%tol, 4.0_wp*geo%tol])) return
         end do
         refused_before = .false.
         if (.not. allocated(geo%refused_keys)) allocate (geo%refused_keys(6, 16))
         if (geo%nrefused_keys >= size(geo%refused_keys, 2)) then
            allocate (grown(6, 2*size(geo%refused_keys, 2)))
            grown(:, 1:geo%nrefused_keys) = geo%refused_keys(:, 1:geo%nrefused_keys)
            call move_alloc(grown, geo%refused_keys)
         end if
         geo%nrefused_keys = geo%nrefused_keys + 1
         geo%refused_keys(:, geo%nrefused_keys) = key
      end function refused_before
   end subroutine split_block_path_as

   !> A cut of block b would leave the sliver (tx, ty) beside the piece
   !> (rx, ry). The sliver is merged into the neighbour across its longest
   !> edge that is not on the cut's line, so the new joint stays whole and
   !> the old one bends there; block b becomes (rx, ry). Where that edge has
   !> no neighbour (the model's boundary, an opening) or the union is not
   !> valid, the next longest edge with a neighbour is tried. `ok` is false,
   !> and nothing changes, when no union is valid (simple, both areas, no new
   !> edge below EDGE): the caller refuses the cut. Slivers are never
   !> deleted (see below).
   subroutine absorb_sliver(geo, b, tx, ty, rx, ry, px, py, ok, clear)
      type(geometry_t), intent(inout) :: geo
      !> drop the pending crack parts along the stretch merged across (a
      !> TUNNEL ring's cut; pending_clear_stretch)
      logical, intent(in) :: clear
      integer(ip), intent(in) :: b
      real(wp), intent(in) :: tx(:), ty(:), rx(:), ry(:), px(:), py(:)
      logical, intent(out) :: ok
      real(wp), allocatable :: nx_(:), ny_(:), ux_(:), uy_(:), elen(:)
      integer(ip), allocatable :: order(:), edge(:)
      integer(ip) :: i, j, n, best_nb, k, nedge
      real(wp) :: best, bt0, bt1
      ok = .false.
      n = size(tx)
      ! the sliver's edges that are not part of the cut (nor on the cut's
      ! line: merging across that would hand the sliver back and forth
      ! between the two sides of the cut), longest first
      allocate (edge(n), elen(n))
      nedge = 0
      do i = 1, n
         j = merge(1_ip, i + 1_ip, i == n)
         if (on_cut_line(tx(i), ty(i), tx(j), ty(j))) cycle
         nedge = nedge + 1
         edge(nedge) = i
         elen(nedge) = -hypot(tx(j) - tx(i), ty(j) - ty(i))   ! longest first
      end do
      allocate (order(nedge))
      call sort_order(elen(1:nedge), order)
      ! merged across the longest such edge that has a neighbour and gives
      ! a valid union. A sliver with no such edge (on the model's edge or an
      ! opening, and no valid union across its other edges) is not deleted:
      ! that left a notch narrower than ROUND in the boundary, whose faces
      ! the boundary's loads cannot tell from a closed joint, so BOUNDARY
      ! STRESS no longer closed and a model held by it turned (a random
      ! 20 m square: 1.3e7 N missing). The cut is refused instead (`ok`
      ! false): the joint stops at this block, ROUND or less short of the edge.
      do k = 1, nedge
         call neighbour_across(edge(order(k)), best_nb, best, bt0, bt1)
         if (best_nb == 0 .or. best <= 10.0_wp*geo%tol) cycle
         call try_merge(edge(order(k)), best_nb, bt0, bt1, ok)
         if (ok) then
            geo%cut_stats(cut_made) = geo%cut_stats(cut_made) + 1
            geo%cut_stats(cut_sliver_merged) = geo%cut_stats(cut_sliver_merged) + 1
            return
         end if
      end do
   contains
      !> The neighbour sharing the longest stretch [t0, t1] of edge e.
      subroutine neighbour_across(e, nb, over_best, t0b, t1b)
         integer(ip), intent(in) :: e
         integer(ip), intent(out) :: nb
         real(wp), intent(out) :: over_best, t0b, t1b
         integer(ip) :: m, e2
         real(wp) :: ax_, ay_, bx_, by_, l_, ex_, ey_, o_, s0, s1
         nb = 0
         over_best = 0.0_wp
         t0b = 0.0_wp
         t1b = 0.0_wp
         e2 = merge(1_ip, e + 1_ip, e == n)
         ax_ = tx(e); ay_ = ty(e); bx_ = tx(e2); by_ = ty(e2)
         l_ = hypot(bx_ - ax_, by_ - ay_)
         if (l_ <= 0.0_wp) return
         ex_ = (bx_ - ax_)/l_
         ey_ = (by_ - ay_)/l_
         do m = 1, geo%blocks%n
            if (m == b .or. .not. geo%blocks%live(m)) cycle
            if (geo%blocks%xmax(m) < min(ax_, bx_) - geo%tol .or. &
                geo%blocks%xmin(m) > max(ax_, bx_) + geo%tol) cycle
            if (geo%blocks%ymax(m) < min(ay_, by_) - geo%tol .or. &
                geo%blocks%ymin(m) > max(ay_, by_) + geo%tol) cycle
            call shared_stretch(m, ax_, ay_, ex_, ey_, l_, o_, s0, s1)
            if (o_ > over_best) then
               over_best = o_
               nb = m
               t0b = s0
               t1b = s1
            end if
         end do
      end subroutine neighbour_across

      !> Merge the sliver into block nb across edge e (shared stretch
      !> [t0, t1]); `done` false, and nothing changed, if the union is not
      !> simple, does not hold exactly the two areas or adds an edge below
      !> EDGE.
      subroutine try_merge(e, nb, t0, t1, done)
         integer(ip), intent(in) :: e, nb
         real(wp), intent(in) :: t0, t1
         logical, intent(out) :: done
         integer(ip) :: e2, q, q2
         real(wp) :: ax_, ay_, l_, ex_, ey_, a2
         done = .false.
         e2 = merge(1_ip, e + 1_ip, e == n)
         ax_ = tx(e); ay_ = ty(e)
         l_ = hypot(tx(e2) - ax_, ty(e2) - ay_)
         ex_ = (tx(e2) - ax_)/l_
         ey_ = (ty(e2) - ay_)/l_
         ! the union: the neighbour from P1 round to P2, then the sliver from
         ! P2 round to P1, where P1 < P2 bound the shared stretch along the edge
         call geometry_block_polygon(geo, nb, nx_, ny_)
         call with_point(nx_, ny_, ax_ + t0*ex_, ay_ + t0*ey_)
         call with_point(nx_, ny_, ax_ + t1*ex_, ay_ + t1*ey_)
         ux_ = tx
         uy_ = ty
         call with_point(ux_, uy_, ax_ + t0*ex_, ay_ + t0*ey_)
         call with_point(ux_, uy_, ax_ + t1*ex_, ay_ + t1*ey_)
         call join(nx_, ny_, ux_, uy_, ax_ + t0*ex_, ay_ + t0*ey_, ax_ + t1*ex_, ay_ + t1*ey_, done)
         if (.not. done) return
         done = .false.
         ! ux_, uy_ now hold the union
         do q = 1, size(ux_)
            q2 = merge(1_ip, q + 1_ip, q == size(ux_))
            if (hypot(ux_(q2) - ux_(q), uy_(q2) - uy_(q)) < geo%edge_min - geo%tol) then
               ! a short edge is harmless only where it was already there
               if (.not. old_edge(nb, ux_(q), uy_(q), ux_(q2), uy_(q2))) return
            end if
         end do
         if (.not. polygon_is_simple(ux_, uy_, geo%tol)) return
         ! the union must hold exactly the two areas (clockwise: negative signed)
         a2 = -polygon_signed_area(tx, ty) + geo%blocks%area(nb)
         if (abs(-polygon_signed_area(ux_, uy_) - a2) > 1.0e-9_wp*a2) return
         call geometry_set_block_polygon(geo, b, rx, ry)
         call geometry_set_block_polygon(geo, nb, ux_, uy_)
         if (clear) call pending_clear_stretch(geo, ax_ + t0*ex_, ay_ + t0*ey_, ax_ + t1*ex_, &
                                               ay_ + t1*ey_)
         done = .true.
      end subroutine try_merge

      !> Whether segment c-d lies on the line of a step of the cut path.
      logical function on_cut_line(cx, cy, dx, dy)
         real(wp), intent(in) :: cx, cy, dx, dy
         integer(ip) :: q
         real(wp) :: lx, ly, ll
         on_cut_line = .false.
         do q = 1, size(px) - 1
            lx = px(q + 1) - px(q)
            ly = py(q + 1) - py(q)
            ll = hypot(lx, ly)
            if (ll <= 0.0_wp) cycle
            if (abs((cx - px(q))*ly - (cy - py(q))*lx)/ll <= 4.0_wp*geo%tol .and. &
                abs((dx - px(q))*ly - (dy - py(q))*lx)/ll <= 4.0_wp*geo%tol) then
               on_cut_line = .true.
               return
            end if
         end do
      end function on_cut_line
      logical function same(x1_, y1_, x2_, y2_)
         real(wp), intent(in) :: x1_, y1_, x2_, y2_
         same = hypot(x2_ - x1_, y2_ - y1_) <= 4.0_wp*geo%tol
      end function same
      !> Length [t0, t1] along the edge (a + t e, 0 <= t <= len) that block m's
      !> boundary runs along in the opposite direction (one contiguous stretch:
      !> the hull of the collinear pieces).
      subroutine shared_stretch(m, ax, ay, ex, ey, len, over, t0, t1)
         integer(ip), intent(in) :: m
         real(wp), intent(in) :: ax, ay, ex, ey, len
         real(wp), intent(out) :: over, t0, t1
         real(wp), allocatable :: mx(:), my(:)
         integer(ip) :: q, q2, npiece
         real(wp) :: dc, dd, tc, td, lo, hi, sum
         call geometry_block_polygon(geo, m, mx, my)
         t0 = huge(1.0_wp)
         t1 = -huge(1.0_wp)
         sum = 0.0_wp
         npiece = 0
         do q = 1, size(mx)
            q2 = merge(1_ip, q + 1_ip, q == size(mx))
            dc = (mx(q) - ax)*(-ey) + (my(q) - ay)*ex
            dd = (mx(q2) - ax)*(-ey) + (my(q2) - ay)*ex
            if (abs(dc) > 4.0_wp*geo%tol .or. abs(dd) > 4.0_wp*geo%tol) cycle
            tc = (mx(q) - ax)*ex + (my(q) - ay)*ey
            td = (mx(q2) - ax)*ex + (my(q2) - ay)*ey
            if (td >= tc) cycle            ! same direction: not a facing edge
            lo = max(0.0_wp, td)
            hi = min(len, tc)
            if (hi - lo <= geo%tol) cycle
            sum = sum + (hi - lo)
            npiece = npiece + 1
            t0 = min(t0, lo)
            t1 = max(t1, hi)
         end do
         over = 0.0_wp
         ! only a contiguous stretch can be joined across (t0, t1 are unset
         ! without a piece: Fortran does not short-circuit .and.)
         if (npiece > 0) then
            if (abs((t1 - t0) - sum) <= 10.0_wp*geo%tol) over = sum
         end if
      end subroutine shared_stretch
      !> Insert point (qx, qy) into the polygon where it lies on an edge (not
      !> when it is already a corner).
      subroutine with_point(wx, wy, qx, qy)
         real(wp), allocatable, intent(inout) :: wx(:), wy(:)
         real(wp), intent(in) :: qx, qy
         integer(ip) :: q, q2, nq
         real(wp) :: d, t
         nq = size(wx)
         do q = 1, nq
            if (same(wx(q), wy(q), qx, qy)) return
         end do
         do q = 1, nq
            q2 = merge(1_ip, q + 1_ip, q == nq)
            call segment_distance(qx, qy, wx(q), wy(q), wx(q2), wy(q2), d, t)
            if (d <= 4.0_wp*geo%tol .and. t > 0.0_wp .and. t < 1.0_wp) then
               wx = [wx(1:q), qx, wx(q + 1:nq)]
               wy = [wy(1:q), qy, wy(q + 1:nq)]
               return
            end if
         end do
      end subroutine with_point
      !> Union of polygon n (neighbour) and polygon u (sliver) that share the
      !> stretch p1 -> p2 (u's direction); the result goes to u.
      subroutine join(nx, ny, ux, uy, p1x, p1y, p2x, p2y, good)
         real(wp), allocatable, intent(inout) :: nx(:), ny(:), ux(:), uy(:)
         real(wp), intent(in) :: p1x, p1y, p2x, p2y
         logical, intent(out) :: good
         real(wp), allocatable :: wx(:), wy(:)
         integer(ip) :: i1n, i2n, i1u, i2u, q, cnt
         good = .false.
         i1n = find(nx, ny, p1x, p1y)
         i2n = find(nx, ny, p2x, p2y)
         i1u = find(ux, uy, p1x, p1y)
         i2u = find(ux, uy, p2x, p2y)
         if (min(i1n, i2n, i1u, i2u) == 0) return
         allocate (wx(size(nx) + size(ux)), wy(size(nx) + size(ux)))
         cnt = 0
         ! neighbour: forward from P1 to P2
         q = i1n
         do
            cnt = cnt + 1
            wx(cnt) = nx(q)
            wy(cnt) = ny(q)
            if (q == i2n) exit
            q = merge(1_ip, q + 1_ip, q == size(nx))
            if (cnt > size(nx)) return
         end do
         ! sliver: forward from after P2 to before P1
         q = merge(1_ip, i2u + 1_ip, i2u == size(ux))
         do while (q /= i1u)
            cnt = cnt + 1
            wx(cnt) = ux(q)
            wy(cnt) = uy(q)
            q = merge(1_ip, q + 1_ip, q == size(ux))
            if (cnt > size(wx) - 1) return
         end do
         ux = wx(1:cnt)
         uy = wy(1:cnt)
         good = cnt >= 3
      end subroutine join
      integer(ip) function find(wx, wy, qx, qy)
         real(wp), intent(in) :: wx(:), wy(:), qx, qy
         integer(ip) :: q
         find = 0
         do q = 1, size(wx)
            if (same(wx(q), wy(q), qx, qy)) then
               find = q
               return
            end if
         end do
      end function find
      !> Whether c-d is (part of) an edge block m had before.
      logical function old_edge(m, cx, cy, dx, dy)
         integer(ip), intent(in) :: m
         real(wp), intent(in) :: cx, cy, dx, dy
         real(wp), allocatable :: mx(:), my(:)
         integer(ip) :: q, q2
         call geometry_block_polygon(geo, m, mx, my)
         old_edge = .false.
         do q = 1, size(mx)
            q2 = merge(1_ip, q + 1_ip, q == size(mx))
            if (same(mx(q), my(q), cx, cy) .and. same(mx(q2), my(q2), dx, dy)) then
               old_edge = .true.
               return
            end if
         end do
      end function old_edge
   end subroutine absorb_sliver

   !> The stretch p-q of an edge a sliver was merged across is inside a block
   !> now: the parts of pending crack segments lying along it are dropped. A
   !> pending segment along that joint (a JSET crack kept whole because it was
   !> partial elsewhere) otherwise cut the sliver off again at the next crack
   !> that touched the block, and the merge back failed: a joint grazing a
   !> TUNNEL ring gave 48 refused cuts of one sliver, which stayed.
   subroutine pending_clear_stretch(geo, px, py, qx, qy)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: px, py, qx, qy
      integer(ip) :: i, m, nadd
      real(wp) :: len, ex, ey, d1, d2, s1, s2, tl
      real(wp), allocatable :: add(:, :)
      len = hypot(qx - px, qy - py)
      if (len <= geo%tol) return
      ex = (qx - px)/len
      ey = (qy - py)/len
      tl = 4.0_wp*geo%tol
      allocate (add(4, 8))
      nadd = 0
      m = 0
      do i = 1, geo%pending%n
         associate (x1 => geo%pending%x1(i), y1 => geo%pending%y1(i), &
                    x2 => geo%pending%x2(i), y2 => geo%pending%y2(i))
            d1 = (x1 - px)*(-ey) + (y1 - py)*ex
            d2 = (x2 - px)*(-ey) + (y2 - py)*ex
            s1 = min((x1 - px)*ex + (y1 - py)*ey, (x2 - px)*ex + (y2 - py)*ey)
            s2 = max((x1 - px)*ex + (y1 - py)*ey, (x2 - px)*ex + (y2 - py)*ey)
         end associate
         if (abs(d1) > tl .or. abs(d2) > tl .or. min(s2, len) - max(s1, 0.0_wp) <= tl) then
            m = m + 1
            geo%pending%x1(m) = geo%pending%x1(i)
            geo%pending%y1(m) = geo%pending%y1(i)
            geo%pending%x2(m) = geo%pending%x2(i)
            geo%pending%y2(m) = geo%pending%y2(i)
            cycle
         end if
         ! the parts before and after the stretch stay pending
         if (nadd + 2 > size(add, 2)) add = reshape([add, 0.0_wp*add], [4, 2*size(add, 2)])
         if (s1 < -tl) then
            nadd = nadd + 1
            add(:, nadd) = [px + s1*ex, py + s1*ey, px, py]
         end if
         if (s2 > len + tl) then
            nadd = nadd + 1
            add(:, nadd) = [qx, qy, px + s2*ex, py + s2*ey]
         end if
      end do
      geo%pending%n = m
      do i = 1, nadd
         call geometry_add_pending(geo, add(1, i), add(2, i), add(3, i), add(4, i))
      end do
   end subroutine pending_clear_stretch

   !> Live blocks whose bounding box the segment's line passes through.
   subroutine blocks_along(geo, ax, ay, bx, by, list, n)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: ax, ay, bx, by
      integer(ip), allocatable, intent(out) :: list(:)
      integer(ip), intent(out) :: n
      integer(ip) :: b
      real(wp) :: nx, ny, f1, f2, f3, f4, t
      allocate (list(64))
      n = 0
      nx = -(by - ay)
      ny = bx - ax
      t = geo%tol*hypot(nx, ny)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         associate (x0 => geo%blocks%xmin(b) - geo%tol, x1 => geo%blocks%xmax(b) + geo%tol, &
                    y0 => geo%blocks%ymin(b) - geo%tol, y1 => geo%blocks%ymax(b) + geo%tol)
            if (max(ax, bx) < x0 .or. min(ax, bx) > x1) cycle
            if (max(ay, by) < y0 .or. min(ay, by) > y1) cycle
            ! the box corners must not all lie on one side of the line
            f1 = nx*(x0 - ax) + ny*(y0 - ay)
            f2 = nx*(x1 - ax) + ny*(y0 - ay)
            f3 = nx*(x0 - ax) + ny*(y1 - ay)
            f4 = nx*(x1 - ax) + ny*(y1 - ay)
            if (min(f1, f2, f3, f4) > t .or. max(f1, f2, f3, f4) < -t) cycle
         end associate
         call push_back(list, n, b)
      end do
   end subroutine blocks_along

end module geometry_cutting
