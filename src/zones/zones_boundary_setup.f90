!> Geometry of BOUNDARY (manual Section 4.5): which corners lie on the free
!> surface of the block assembly, the order of the outer boundary (BOUNDARY
!> CORNER ic1 ic2) and the equivalent corner forces of a boundary stress.
!>
!> Free surface: an edge of a live block is free near one of its ends when
!> a point a little outside the edge, a quarter of the edge from that end,
!> lies in no live block. Testing near each end (not at the midpoint) keeps
!> a T-junction of the neighbours from looking like a gap. The offset is
!> min(edge/10, rounding length, (but at least 10 tolerances)): blocks that
!> are farther apart than the rounding length are not in contact anyway.
!> A corner is a boundary point when one of its two edges is free near it.
!>
!> Boundary stress: the consistent corner forces of the traction sigma.n (n
!> the outward normal of the edge) over each free edge next to the corner.
!> For a stress varying linearly in x and y the traction t is linear along
!> the edge, and the two corner forces L (2 t_corner + t_other) / 6 and
!> L (t_corner + 2 t_other) / 6 have the traction's resultant and its moment:
!> (L/2) times the traction at the third point of the edge from the corner.
!> (The half edge's own integral, L (3 t_corner + t_other) / 8 at its quarter
!> point, has the resultant but puts it at the corner: a moment L^3 g / 24
!> short for a gradient g along the edge, which turned rigid blocks held by a
!> gravity-gradient boundary stress.) Under SET FUP the stress at the third
!> point is kept (boundary_stress_sides) and the engine takes L n from the
!> current geometry each step (zones_boundary). A gridpoint (the corner of a
!> zoned block) takes the same consistent force since session 41: it is the
!> discretisation of a linear traction on an edge whose displacement is
!> linear, and with the half edge's quarter-point integral zoned models
!> under INSITU and the same BOUNDARY STRESS with gravity's gradient
!> drifted at rest (docs/robustness.md).
module zones_boundary_setup
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use model_geometry, only: geometry_t, block_contains_point
   use model_boundary, only: boundary_t, boundary_add_point, boundary_index
   implicit none
   private
   public :: block_grid_t, block_grid_build, point_in_blocks, corner_free_sides, boundary_opening_points
   public :: boundary_extend, boundary_stress_force, boundary_stress_sides, boundary_walk, &
             boundary_mouth_sides, boundary_range_ends, &
             stress_at

   !> Uniform bins over the live blocks' bounding boxes, for point queries.
   type :: block_grid_t
      integer :: nx = 0, ny = 0
      real(wp) :: x0 = 0.0_wp, y0 = 0.0_wp, h = 1.0_wp
      integer, allocatable :: start(:)        !< CSR over cells, size nx*ny+1
      integer(ip), allocatable :: blocks(:)
      real(wp), allocatable :: xmin(:), xmax(:), ymin(:), ymax(:)   !< per block
   end type block_grid_t

   !> Fraction of the edge from the corner where the free-surface test looks.
   real(wp), parameter :: sample_fraction = 0.25_wp

   !> Rules of nearest_partner: which boundary point continues the free
   !> surface; at a joint mouth (`mouth_rules`) the first that finds one.
   integer, parameter :: partner_loaded = 1, partner_sole_loaded = 2, partner_t_junction = 3, &
                         partner_bridge = 4
   integer, parameter :: mouth_rules(3) = [partner_sole_loaded, partner_t_junction, partner_bridge]

contains

   !> Bin the live blocks of `geo` (boxes from the current corner positions).
   subroutine block_grid_build(geo, grid)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(out) :: grid
      integer(ip) :: b, c, i, nlive
      integer :: ix0, ix1, iy0, iy1, jx, jy, cell, pass
      real(wp) :: xlo, xhi, ylo, yhi
      integer, allocatable :: fill(:)
      nlive = 0
      xlo = huge(1.0_wp); xhi = -huge(1.0_wp); ylo = huge(1.0_wp); yhi = -huge(1.0_wp)
      allocate (grid%xmin(geo%blocks%n), grid%xmax(geo%blocks%n), grid%ymin(geo%blocks%n), &
                grid%ymax(geo%blocks%n))
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         nlive = nlive + 1
         c = geo%blocks%first_corner(b)
         grid%xmin(b) = geo%corners%x(c); grid%xmax(b) = geo%corners%x(c)
         grid%ymin(b) = geo%corners%y(c); grid%ymax(b) = geo%corners%y(c)
         do i = 1, geo%blocks%ncorner(b)
            grid%xmin(b) = min(grid%xmin(b), geo%corners%x(c))
            grid%xmax(b) = max(grid%xmax(b), geo%corners%x(c))
            grid%ymin(b) = min(grid%ymin(b), geo%corners%y(c))
            grid%ymax(b) = max(grid%ymax(b), geo%corners%y(c))
            c = geo%corners%next(c)
         end do
         xlo = min(xlo, grid%xmin(b)); xhi = max(xhi, grid%xmax(b))
         ylo = min(ylo, grid%ymin(b)); yhi = max(yhi, grid%ymax(b))
      end do
      if (nlive == 0) then
         grid%nx = 1; grid%ny = 1
         allocate (grid%start(2), grid%blocks(0))
         grid%start = 1
         return
      end if
      grid%h = max(sqrt(max(xhi - xlo, tiny(1.0_wp))*max(yhi - ylo, tiny(1.0_wp)) &
                        /real(nlive, wp)), max(xhi - xlo, yhi - ylo)/2048.0_wp, tiny(1.0_wp))
      grid%x0 = xlo
      grid%y0 = ylo
      grid%nx = max(1, min(2048, int((xhi - xlo)/grid%h) + 1))
      grid%ny = max(1, min(2048, int((yhi - ylo)/grid%h) + 1))
      allocate (grid%start(grid%nx*grid%ny + 1), fill(grid%nx*grid%ny))
      grid%start = 0
      fill = 0
      ! pass 1 counts, pass 2 stores
      do pass = 1, 2
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            ix0 = cell_x(grid, grid%xmin(b)); ix1 = cell_x(grid, grid%xmax(b))
            iy0 = cell_y(grid, grid%ymin(b)); iy1 = cell_y(grid, grid%ymax(b))
            do jy = iy0, iy1
               do jx = ix0, ix1
                  cell = (jy - 1)*grid%nx + jx
                  if (pass == 1) then
                     fill(cell) = fill(cell) + 1
                  else
                     grid%blocks(grid%start(cell) + fill(cell)) = b
                     fill(cell) = fill(cell) + 1
                  end if
               end do
            end do
         end do
         if (pass == 1) then
            grid%start(1) = 1
            do cell = 1, grid%nx*grid%ny
               grid%start(cell + 1) = grid%start(cell) + fill(cell)
            end do
            allocate (grid%blocks(grid%start(grid%nx*grid%ny + 1) - 1))
            fill = 0
         end if
      end do
   end subroutine block_grid_build

   pure integer function cell_x(grid, x) result(i)
      type(block_grid_t), intent(in) :: grid
      real(wp), intent(in) :: x
      i = max(1, min(grid%nx, int((x - grid%x0)/grid%h) + 1))
   end function cell_x

   pure integer function cell_y(grid, y) result(i)
      type(block_grid_t), intent(in) :: grid
      real(wp), intent(in) :: y
      i = max(1, min(grid%ny, int((y - grid%y0)/grid%h) + 1))
   end function cell_y

   !> Does (px, py) lie inside a live block (crossing number on its ring)?
   logical function point_in_blocks(geo, grid, px, py) result(inside)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      real(wp), intent(in) :: px, py
      integer :: cell, k
      integer(ip) :: b
      inside = .false.
      ! outside the binned area the clamped cell is searched; the box test rejects
      cell = (cell_y(grid, py) - 1)*grid%nx + cell_x(grid, px)
      do k = grid%start(cell), grid%start(cell + 1) - 1
         b = grid%blocks(k)
         if (px < grid%xmin(b) .or. px > grid%xmax(b) .or. py < grid%ymin(b) .or. &
             py > grid%ymax(b)) cycle
         if (block_contains_point(geo, b, px, py)) then
            inside = .true.
            return
         end if
      end do
   end function point_in_blocks

   !> Is the edge of a block that leaves (ax, ay) along (dx, dy) free near
   !> that end? Outward normal (-dy, dx)/L (the edge clockwise; a caller with
   !> the edge the other way round passes its direction and normal flipped
   !> through `flip`). Sampled near that end, at `sample_fraction` along it
   !> but at most ROUND from the corner (an edge partly covered by a
   !> neighbour, a T-junction on the model's edge, is judged by its part at
   !> the corner; pieces of edges are at least EDGE = 2 ROUND long), at three
   !> offsets outward: d = min(0.1 L, ROUND), 0.1 d and 10 tol. The edge is
   !> free only if every sample is outside all blocks: the largest offset
   !> spans a joint that has opened; the smaller ones stay inside a thin
   !> neighbour (a sliver along the model's edge, 0.06 m thick where d is
   !> 0.1) that the largest one passes over. Before, that sliver's neighbour
   !> counted as free there and took a boundary stress on an inner edge:
   !> the tractions no longer closed and a model held by them turned.
   !> Where only the sample right at the edge is outside (a block within d:
   !> the far side of an opened joint, or of a narrow notch near its tip),
   !> the same three samples at the edge's middle decide: a notch widens
   !> away from its tip, a joint does not.
   logical function edge_free_from(geo, grid, ax, ay, dx, dy, flip) result(free)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      real(wp), intent(in) :: ax, ay, dx, dy
      logical, intent(in) :: flip
      real(wp) :: l, d, sx, sy, nx, ny, off(3), along
      integer :: k
      free = .false.
      l = hypot(dx, dy)
      if (l <= 0.0_wp) return
      nx = -dy/l
      ny = dx/l
      if (flip) then
         nx = -nx
         ny = -ny
      end if
      d = max(min(0.1_wp*l, geo%round), 10.0_wp*geo%tol)
      off = [10.0_wp*geo%tol, max(0.1_wp*d, 10.0_wp*geo%tol), d]
      along = min(sample_fraction, max(geo%round, 10.0_wp*geo%tol)/l)
      if (all_outside(along, 1)) then
         free = .true.
      else if (.not. point_in_blocks(geo, grid, ax + along*dx + off(1)*nx, ay + along*dy + off(1)*ny)) then
         ! nothing right at the edge, but a block within d: the far side of
         ! a narrow notch (a sliver deleted on the model's edge) or of an
         ! opened joint; the edge's middle tells them apart
         free = all_outside(0.5_wp, 1)
      end if
   contains
      logical function all_outside(f, k0)
         real(wp), intent(in) :: f
         integer, intent(in) :: k0
         all_outside = .false.
         do k = k0, 3
            sx = ax + f*dx + off(k)*nx
            sy = ay + f*dy + off(k)*ny
            if (point_in_blocks(geo, grid, sx, sy)) return
         end do
         all_outside = .true.
      end function all_outside
   end function edge_free_from

   !> Is the edge between corners a and b (of one block) free near a? `a`
   !> first in its block's clockwise order (the edge a -> b) unless `flip`
   !> (the edge b -> a).
   logical function edge_free_near(geo, grid, a, b, flip) result(free)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: a, b
      logical, intent(in) :: flip
      free = edge_free_from(geo, grid, geo%corners%x(a), geo%corners%y(a), &
                            geo%corners%x(b) - geo%corners%x(a), &
                            geo%corners%y(b) - geo%corners%y(a), flip)
   end function edge_free_near

   !> Free sides of corner c: the edge prev(c)->c near c, the edge c->next(c) near c.
   subroutine corner_free_sides(geo, grid, c, free_prev, free_next)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      logical, intent(out) :: free_prev, free_next
      ! the edge prev->c, seen from c, runs c->prev with the outward normal on
      ! the other side: test it as the reversed edge with the normal flipped
      free_prev = edge_free_near(geo, grid, c, geo%corners%prev(c), .true.)
      free_next = edge_free_near(geo, grid, c, geo%corners%next(c), .false.)
   end subroutine corner_free_sides

   !> The sides of boundary corner c that carry a boundary load. A side is
   !> loaded when it is free near c, or free near its other end o while no
   !> T-junction cuts it short from o (a block's corner on it, the rest of
   !> the edge covered). Both ends of an edge then agree whether it is
   !> loaded, so the loaded edges close into loops: a notch in an opening's
   !> wall that narrows to a closed tip (free at its mouth, taken for a
   !> closed joint at its tip; TUNNEL next to dense joints, or a DELETE
   !> that takes a wedge out of the wall) was loaded at its mouth corner
   !> only, and the loads of a model held by its in-situ stress missed up
   !> to 1e7 N (stability.boundary_closure_random with tunnels: 9 of 200
   !> scenes before). Its tip corners become boundary points, where the
   !> surface passes to the block across the notch (a joint mouth).
   subroutine loaded_sides(bnd, geo, grid, c, fp, fn)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      logical, intent(out) :: fp, fn
      integer(ip) :: o
      logical :: op, on
      call corner_free_sides(geo, grid, c, fp, fn)
      if (.not. fn) then
         o = geo%corners%next(c)
         call corner_free_sides(geo, grid, o, op, on)
         if (op) fn = t_junction(bnd, geo, grid, o, .false.) == 0
      end if
      if (.not. fp) then
         o = geo%corners%prev(c)
         call corner_free_sides(geo, grid, o, op, on)
         if (on) fp = t_junction(bnd, geo, grid, o, .true.) == 0
      end if
   end subroutine loaded_sides


   !> Add the corners on the free surface to the list: all of them the first
   !> time, afterwards only corners created since the last BOUNDARY (corner id
   !> above `corners_seen`), so that a hole made by DELETE after the first
   !> BOUNDARY does not join the boundary (docs/zones.md).
   subroutine boundary_extend(bnd, geo, grid, nadded)
      type(boundary_t), intent(inout) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(out) :: nadded
      integer(ip) :: i
      logical :: first
      logical, allocatable :: listed(:)
      nadded = 0
      first = bnd%n == 0
      allocate (listed(max(1_ip, geo%corners%n)))
      listed = .false.
      do i = 1, bnd%n
         if (bnd%corner(i) <= geo%corners%n) listed(bnd%corner(i)) = .true.
      end do
      call add_pass(.false.)
      ! the tips of notches: corners loaded only from their edges' far ends
      ! (loaded_sides; needs the T-junction corners listed by the first pass)
      call add_pass(.true.)
      bnd%corners_seen = geo%corners%n
   contains
      !> Add every corner not yet listed (new since the last BOUNDARY, or all
      !> the first time) with a free side, or with a loaded one (`loaded`).
      subroutine add_pass(loaded)
         logical, intent(in) :: loaded
         integer(ip) :: b, c, k, id
         logical :: fp, fn
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            c = geo%blocks%first_corner(b)
            do k = 1, geo%blocks%ncorner(b)
               if ((c > bnd%corners_seen .or. first) .and. .not. listed(c)) then
                  if (loaded) then
                     call loaded_sides(bnd, geo, grid, c, fp, fn)
                  else
                     call corner_free_sides(geo, grid, c, fp, fn)
                  end if
                  if (fp .or. fn) then
                     call boundary_add_point(bnd, c, id)
                     listed(c) = .true.
                     nadded = nadded + 1
                  end if
               end if
               c = geo%corners%next(c)
            end do
         end do
      end subroutine add_pass
   end subroutine boundary_extend

   !> Stress at (x, y): s0 + gx x + gy y, components (sxx, sxy, syy).
   pure function stress_at(s0, gx, gy, x, y) result(s)
      real(wp), intent(in) :: s0(3), gx(3), gy(3), x, y
      real(wp) :: s(3)
      s = s0 + gx*x + gy*y
   end function stress_at

   !> The stress a boundary half edge from corner c towards corner o carries
   !> (module header): the field at the edge's third point from c, on every
   !> corner, a rigid or SDEF block's or a gridpoint.
   pure function third_point_stress(geo, c, o, s0, gx, gy) result(s)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c, o
      real(wp), intent(in) :: s0(3), gx(3), gy(3)
      real(wp) :: s(3), w
      w = 2.0_wp/3.0_wp
      s = stress_at(s0, gx, gy, w*geo%corners%x(c) + (1.0_wp - w)*geo%corners%x(o), &
                    w*geo%corners%y(c) + (1.0_wp - w)*geo%corners%y(o))
   end function third_point_stress

   !> The stress of the field s0 + gx x + gy y on the halves of the free
   !> edges next to corner c (module header): `s_prev` on the half of the
   !> edge to the previous corner of its block, `s_next` on the half to the
   !> next one, each the stress at the edge's third point, zero for
   !> a half edge that is not loaded. With `bnd` (the boundary list) and
   !> `t_prev` / `t_next`: a free side that another block's boundary corner
   !> cuts short (a T-junction: that corner lies on the edge, the rest of
   !> the edge is covered by its block) ends there; t_* is that corner (0
   !> where the side is whole) and the side's segment runs to it
   !> (zones_boundary's `end_prev` / `end_next`). With `selected` (by corner id: the
   !> points the BOUNDARY line acts on) only the half edges whose other end
   !> is selected too are loaded: a stress on a range acts on the boundary
   !> segments inside it, so the corner of a model where two sides are given
   !> separately (verification C: bottom and sides with their own STRESS
   !> lines) is loaded once by each side, not twice. A selected point with
   !> no selected neighbour takes all its free half edges.
   subroutine boundary_stress_sides(geo, grid, c, s0, gx, gy, s_prev, s_next, selected, &
                                    bnd, t_prev, t_next)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: s0(3), gx(3), gy(3)
      real(wp), intent(out) :: s_prev(3), s_next(3)
      logical, intent(in), optional :: selected(:)
      type(boundary_t), intent(in), optional :: bnd
      integer(ip), intent(out), optional :: t_prev, t_next
      logical :: fp, fn, sp, sn
      integer(ip) :: op, on, tp, tn
      s_prev = 0.0_wp
      s_next = 0.0_wp
      if (present(bnd)) then
         call loaded_sides(bnd, geo, grid, c, fp, fn)
      else
         call corner_free_sides(geo, grid, c, fp, fn)
      end if
      ! each free side's far end: the next / previous corner, or the
      ! T-junction corner that cuts it short
      op = geo%corners%prev(c)
      on = geo%corners%next(c)
      tp = 0
      tn = 0
      if (present(bnd)) then
         if (fn) tn = t_junction(bnd, geo, grid, c, .true., selected)
         if (fp) tp = t_junction(bnd, geo, grid, c, .false., selected)
         if (tn > 0) on = tn
         if (tp > 0) op = tp
      end if
      if (present(selected)) then
         sn = selected(on)
         sp = selected(op)
         if ((fn .and. sn) .or. (fp .and. sp)) then
            fn = fn .and. sn
            fp = fp .and. sp
         else if (present(bnd)) then
            ! not alone where a joint leaves the model at this point: the
            ! other block's corner there continues the range
            if (partner_in_range(bnd, geo, grid, c, selected)) then
               fn = .false.
               fp = .false.
            end if
         end if
      end if
      if (.not. fn) tn = 0
      if (.not. fp) tp = 0
      if (present(t_next)) t_next = tn
      if (present(t_prev)) t_prev = tp
      if (fn) s_next = third_point_stress(geo, c, on, s0, gx, gy)
      if (fp) s_prev = third_point_stress(geo, c, op, s0, gx, gy)
   end subroutine boundary_stress_sides

   !> A BOUNDARY STRESS range that stops one segment short of the model's
   !> corner (`bound -9 9 9.1 9.3 stress ...` on a top running from -9.2 to
   !> 9.2, the sides given with ranges that take the corners): the segment
   !> from its last point c to the corner o has only one end in each line's
   !> range, so no line loads it (boundary_stress_sides) and the model rose
   !> under its own weight. The manual (Section 4.5, BOUNDARY) says only that
   !> the condition acts "over a region"; a rock engineer means the whole
   !> straight edge. So the range's straight edge runs on to the corner where
   !> the boundary turns: o is flagged in `ext` (by boundary index) when c is
   !> selected, c's other neighbour p is selected, p-c-o is straight, the
   !> boundary turns at o (o-c and o's other neighbour not in line), the edge
   !> c-o is free, and neither half of c-o carries a stress yet (under SET
   !> FUP; a side line whose range took c too has loaded it). A footing whose
   !> range ends at a point on a straight top (the next point in line) is not
   !> extended. `csel` is by corner id.
   subroutine boundary_range_ends(bnd, geo, grid, csel, ext)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      logical, intent(in) :: csel(:)
      logical, intent(out) :: ext(:)
      integer(ip) :: i, c, o, p, q, k
      integer :: dir
      logical :: fp, fn, free
      ext = .false.
      do i = 1, bnd%n
         c = bnd%corner(i)
         if (.not. csel(c)) cycle
         call corner_free_sides(geo, grid, c, fp, fn)
         do dir = 1, 2
            ! dir 1: o is the next corner of c's block, 2: the previous one
            if (dir == 1) then
               o = geo%corners%next(c); p = geo%corners%prev(c); free = fn
            else
               o = geo%corners%prev(c); p = geo%corners%next(c); free = fp
            end if
            if (.not. free .or. csel(o) .or. .not. csel(p)) cycle
            k = boundary_index(bnd, o)
            if (k == 0) cycle
            if (dir == 1) then
               q = geo%corners%next(o)
            else
               q = geo%corners%prev(o)
            end if
            if (.not. in_line(p, c, o) .or. in_line(c, o, q)) cycle
            if (bnd%fup) then
               if (dir == 1) then
                  if (side_stressed(i, .false.) .or. side_stressed(k, .true.)) cycle
               else
                  if (side_stressed(i, .true.) .or. side_stressed(k, .false.)) cycle
               end if
            end if
            ext(k) = .true.
         end do
      end do
   contains
      !> Do a-b and b-c run on in the same direction (sine of the turn below 1e-3)?
      logical function in_line(a, b, c3)
         integer(ip), intent(in) :: a, b, c3
         real(wp) :: ux, uy, vx, vy, lu, lv
         ux = geo%corners%x(b) - geo%corners%x(a); uy = geo%corners%y(b) - geo%corners%y(a)
         vx = geo%corners%x(c3) - geo%corners%x(b); vy = geo%corners%y(c3) - geo%corners%y(b)
         lu = hypot(ux, uy); lv = hypot(vx, vy)
         in_line = .false.
         if (lu <= 0.0_wp .or. lv <= 0.0_wp) return
         in_line = abs(ux*vy - uy*vx) < 1.0e-3_wp*lu*lv .and. ux*vx + uy*vy > 0.0_wp
      end function in_line
      !> Does point j's half edge (towards its previous corner: prev) carry a
      !> stress (total or next CYCLE's increment)?
      logical function side_stressed(j, prev)
         integer(ip), intent(in) :: j
         logical, intent(in) :: prev
         if (prev) then
            side_stressed = any([bnd%sxx_prev(j), bnd%sxy_prev(j), bnd%syy_prev(j), &
                                 bnd%dsxx_prev(j), bnd%dsxy_prev(j), bnd%dsyy_prev(j)] /= 0.0_wp)
         else
            side_stressed = any([bnd%sxx_next(j), bnd%sxy_next(j), bnd%syy_next(j), &
                                 bnd%dsxx_next(j), bnd%dsxy_next(j), bnd%dsyy_next(j)] /= 0.0_wp)
         end if
      end function side_stressed
   end subroutine boundary_range_ends

   !> Does another block's boundary corner at corner c's place (a joint
   !> leaving the model there, e.g. at the model's corner) have a free side
   !> to a selected point? Then c, with no selected neighbour of its own, is
   !> not a range's lone point taking all its half edges (the rule of
   !> boundary_stress_sides): a side STRESS line reaching the model's corner
   !> loaded the top half edge of the block on the other side of the joint
   !> too, and the top line loaded it again (seed 36 of
   !> tools/zoned_campaign.py, twice the stress on 1.3 m at the corner).
   logical function partner_in_range(bnd, geo, grid, c, selected) result(yes)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      logical, intent(in) :: selected(:)
      integer(ip) :: k, q
      real(wp) :: tol
      logical :: fp, fn
      yes = .false.
      tol = 1.0e-9_wp*geo%extent
      do k = 1, bnd%n
         q = bnd%corner(k)
         if (q == c .or. .not. selected(q)) cycle
         if (geo%corners%block(q) == geo%corners%block(c)) cycle
         if (abs(geo%corners%x(q) - geo%corners%x(c)) > tol .or. &
             abs(geo%corners%y(q) - geo%corners%y(c)) > tol) cycle
         call corner_free_sides(geo, grid, q, fp, fn)
         if ((fn .and. selected(geo%corners%next(q))) .or. &
             (fp .and. selected(geo%corners%prev(q)))) then
            yes = .true.
            return
         end if
      end do
   end function partner_in_range

   !> Is corner q a live corner of another live block than corner c's?
   pure logical function foreign_point(geo, c, q) result(ok)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c, q
      ok = .false.
      if (q == c .or. .not. geo%corners%live(q)) return
      if (geo%corners%block(q) == geo%corners%block(c)) return
      ok = geo%blocks%live(geo%corners%block(q))
   end function foreign_point

   !> Boundary point q may take the free surface on from corner c: a corner
   !> of another live block (foreign_point), and `selected` (by corner id)
   !> when given.
   pure logical function candidate_point(geo, c, q, selected) result(ok)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c, q
      logical, intent(in), optional :: selected(:)
      ok = foreign_point(geo, c, q)
      if (.not. ok .or. .not. present(selected)) return
      ok = selected(q)
   end function candidate_point

   !> The T-junction on the free side of corner c (the side to its next
   !> corner if `forward`, else to its previous one): the boundary corner t
   !> of another live block, `selected`, nearest to c strictly inside that
   !> edge (within 0.1 ROUND of its line), where the free surface leaves
   !> the edge: t's side towards c free, its other side running along the
   !> edge (covered). 0 if there is none.
   integer(ip) function t_junction(bnd, geo, grid, c, forward, selected) result(best_t)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      logical, intent(in) :: forward
      logical, intent(in), optional :: selected(:)
      integer(ip) :: q, t, o
      real(wp) :: ex, ey, l2, u, dist, tol, best
      logical :: tp, tn
      best_t = 0
      o = merge(geo%corners%next(c), geo%corners%prev(c), forward)
      ex = geo%corners%x(o) - geo%corners%x(c)
      ey = geo%corners%y(o) - geo%corners%y(c)
      l2 = ex*ex + ey*ey
      if (l2 <= 0.0_wp) return
      tol = max(0.1_wp*geo%round, 100.0_wp*geo%tol)
      best = 2.0_wp
      do q = 1, bnd%n
         t = bnd%corner(q)
         if (.not. candidate_point(geo, c, t, selected)) cycle
         u = ((geo%corners%x(t) - geo%corners%x(c))*ex + (geo%corners%y(t) - geo%corners%y(c))*ey)/l2
         if (u <= 0.0_wp .or. u >= 1.0_wp .or. u >= best) cycle
         dist = abs((geo%corners%x(t) - geo%corners%x(c))*ey - (geo%corners%y(t) - geo%corners%y(c))*ex) &
                /sqrt(l2)
         if (dist > tol .or. u*sqrt(l2) <= tol .or. (1.0_wp - u)*sqrt(l2) <= tol) cycle
         call corner_free_sides(geo, grid, t, tp, tn)
         ! walking forward from c the surface reaches t and leaves along t's
         ! next side (its previous side lies on the edge); backward, mirrored
         if (.not. surface_runs_on(forward, tp, tn)) cycle
         best = u
         best_t = t
      end do
   end function t_junction

   !> Where the free surface passes from corner c to another block across a
   !> joint (a joint mouth: one side of c free, the other not), the corner of
   !> the neighbour that continues it (the nearest boundary point of another
   !> live block within the rounding length whose side in the same direction
   !> is free, as boundary_walk follows it) and the stress at the third
   !> point of the gap segment c -> partner. `p_next` / `s_next`: the mouth
   !> is on the side of c's next corner (that edge is the joint), `p_prev` /
   !> `s_prev` on the side of its previous corner; 0 and zero stress where
   !> there is none or the partner is not `selected` (by corner id). The
   !> tractions of SET FUP load this segment too, so that the loaded
   !> boundary is a closed loop however the joint opens or shears: its
   !> tractions then add up to zero force and moment (zones_boundary).
   subroutine boundary_mouth_sides(bnd, geo, grid, c, s0, gx, gy, selected, p_prev, p_next, &
                                   s_prev, s_next)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: s0(3), gx(3), gy(3)
      logical, intent(in) :: selected(:)
      integer(ip), intent(out) :: p_prev, p_next
      real(wp), intent(out) :: s_prev(3), s_next(3)
      logical :: fp, fn
      p_prev = 0
      p_next = 0
      s_prev = 0.0_wp
      s_next = 0.0_wp
      call loaded_sides(bnd, geo, grid, c, fp, fn)
      if (fp .eqv. fn) return
      if (fp) then
         p_next = nearest_partner(bnd, geo, grid, c, .true., mouth_rules, selected)
         if (p_next > 0) s_next = third_point_stress(geo, c, p_next, s0, gx, gy)
      else
         p_prev = nearest_partner(bnd, geo, grid, c, .false., mouth_rules, selected)
         if (p_prev > 0) s_prev = third_point_stress(geo, c, p_prev, s0, gx, gy)
      end if
   end subroutine boundary_mouth_sides

   !> Where the free surface passes on from corner c to another block: the
   !> nearest boundary point of another live block (`selected` ones only,
   !> by corner id, when given) that continues it in the walking direction
   !> (`forward`: c -> it) by the first of `rules` that finds one; its
   !> corner (0 if none) and its boundary list entry `entry`.
   !> partner_loaded: within the rounding length of c (blocks that have
   !> moved apart a little still pass the surface on), its side in the
   !> walking direction (`forward`: its next side) loaded (boundary_walk);
   !> partner_sole_loaded: the same and that side its only loaded one (a
   !> joint mouth). Equally near points: the last one.
   !> partner_t_junction: c on a free edge of the point's block, the same
   !> pair as t_junction finds from the other side, which the surface
   !> follows from c to that edge's far end (forward) or reaches c along
   !> from its near end (backward); the edge must be free all the way to
   !> the point (surface_segment_free): one covered again before its end
   !> (an opening's wall along a joint between two T-junctions) is bridged.
   !> partner_bridge: where the free surface leaves c along a stretch of
   !> another block's edge that is covered at both its ends (a T-junction
   !> at each end: an opening's wall along a joint, its neighbours' corners
   !> on that joint; TUNNEL in dense joints), the point where the surface
   !> comes back to a corner: its side in the walking direction loaded and
   !> the other not, and the straight segment to it free. The segment is
   !> loaded at its two end corners, so the loads close; the block whose
   !> edge it is receives none of it (a debt: docs/zones.md).
   !> With the last two rules, of equally near points the first one.
   integer(ip) function nearest_partner(bnd, geo, grid, c, forward, rules, selected, entry) &
      result(best_c)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      logical, intent(in) :: forward
      integer, intent(in) :: rules(:)
      logical, intent(in), optional :: selected(:)
      integer(ip), intent(out), optional :: entry
      integer(ip) :: q, cand, best_q
      integer :: r, rule
      real(wp) :: best, d
      logical :: cp, cn
      best_q = 0
      do r = 1, size(rules)
         rule = rules(r)
         best = huge(1.0_wp)
         if (rule <= partner_sole_loaded) best = max(geo%round, 100.0_wp*geo%tol)
         do q = 1, bnd%n
            cand = bnd%corner(q)
            if (.not. candidate_point(geo, c, cand, selected)) cycle
            d = corner_distance(geo, c, cand)
            select case (rule)
            case (partner_loaded, partner_sole_loaded)
               if (d > best) cycle
               call loaded_sides(bnd, geo, grid, cand, cp, cn)
               if (.not. merge(cn, cp, forward)) cycle
               if (rule == partner_sole_loaded .and. merge(cp, cn, forward)) cycle
            case (partner_t_junction)
               if (d >= best) cycle
               if (t_junction(bnd, geo, grid, cand, .not. forward, selected) /= c) cycle
               if (.not. surface_segment_free(geo, grid, c, cand, forward)) cycle
            case default
               if (d >= best .or. d <= 10.0_wp*geo%tol) cycle
               call loaded_sides(bnd, geo, grid, cand, cp, cn)
               if (.not. surface_runs_on(forward, cp, cn)) cycle
               if (.not. surface_segment_free(geo, grid, c, cand, forward)) cycle
            end select
            best = d
            best_q = q
         end do
         if (best_q > 0) exit
      end do
      best_c = 0
      if (best_q > 0) best_c = bnd%corner(best_q)
      if (present(entry)) entry = best_q
   end function nearest_partner

   !> Distance between corners a and b.
   pure real(wp) function corner_distance(geo, a, b) result(d)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: a, b
      d = hypot(geo%corners%x(b) - geo%corners%x(a), geo%corners%y(b) - geo%corners%y(a))
   end function corner_distance

   !> Does the free surface, walking `forward` (else backward), run on at a
   !> point whose previous / next sides have the property `prev` / `next`
   !> (free, or loaded): the side ahead has it, the side behind not.
   pure logical function surface_runs_on(forward, prev, next) result(runs)
      logical, intent(in) :: forward, prev, next
      runs = merge(next .and. .not. prev, prev .and. .not. next, forward)
   end function surface_runs_on

   !> Is the straight segment between corners c and q free, walking the
   !> surface from c to q (`forward`) or from q to c? Sampled at a quarter,
   !> half and three quarters of it at the three offsets outward of
   !> edge_free_from (outward: (-dy, dx) for the walking direction).
   logical function surface_segment_free(geo, grid, c, q, forward) result(clear)
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c, q
      logical, intent(in) :: forward
      real(wp) :: ax, ay, dx, dy, l, nx, ny, d, off(3), f
      integer :: j, k
      if (forward) then
         ax = geo%corners%x(c)
         ay = geo%corners%y(c)
         dx = geo%corners%x(q) - ax
         dy = geo%corners%y(q) - ay
      else
         ax = geo%corners%x(q)
         ay = geo%corners%y(q)
         dx = geo%corners%x(c) - ax
         dy = geo%corners%y(c) - ay
      end if
      clear = .true.
      l = hypot(dx, dy)
      if (l <= 10.0_wp*geo%tol) return
      nx = -dy/l
      ny = dx/l
      d = max(min(0.1_wp*l, geo%round), 10.0_wp*geo%tol)
      off = [10.0_wp*geo%tol, max(0.1_wp*d, 10.0_wp*geo%tol), d]
      do j = 1, 3
         f = 0.25_wp*j
         do k = 1, 3
            if (point_in_blocks(geo, grid, ax + f*dx + off(k)*nx, ay + f*dy + off(k)*ny)) then
               clear = .false.
               return
            end if
         end do
      end do
   end function surface_segment_free

   !> Equivalent force at corner c of the stress field s0 + gx x + gy y over
   !> the halves of its free edges next to it, with the present geometry
   !> (the fixed forces of SET -FUP): the traction sigma . n of
   !> boundary_stress_sides times half the edge length, L n = (-dy, dx) for
   !> the edge to the next corner (clockwise), (dy, -dx) to the previous one.
   subroutine boundary_stress_force(bnd, geo, grid, c, s0, gx, gy, fx, fy, selected)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: s0(3), gx(3), gy(3)
      real(wp), intent(out) :: fx, fy
      logical, intent(in), optional :: selected(:)
      real(wp) :: s_prev(3), s_next(3), lnx, lny
      integer(ip) :: o, t_prev, t_next
      call boundary_stress_sides(geo, grid, c, s0, gx, gy, s_prev, s_next, selected, bnd, t_prev, t_next)
      o = geo%corners%next(c)
      if (t_next > 0) o = t_next
      lnx = -0.5_wp*(geo%corners%y(o) - geo%corners%y(c))
      lny = 0.5_wp*(geo%corners%x(o) - geo%corners%x(c))
      fx = s_next(1)*lnx + s_next(2)*lny
      fy = s_next(2)*lnx + s_next(3)*lny
      o = geo%corners%prev(c)
      if (t_prev > 0) o = t_prev
      lnx = 0.5_wp*(geo%corners%y(o) - geo%corners%y(c))
      lny = -0.5_wp*(geo%corners%x(o) - geo%corners%x(c))
      fx = fx + s_prev(1)*lnx + s_prev(2)*lny
      fy = fy + s_prev(2)*lnx + s_prev(3)*lny
   end subroutine boundary_stress_force

   !> Which boundary points lie on the wall of an opening (a hole inside the
   !> model) rather than on its outer boundary. The manual's BOUNDARY acts on
   !> the outer boundary (Section 4.5 PLOT BOUNDARY: "outer boundary"; the
   !> domain commands: "all domains except the outer domain"), so a
   !> BOUNDARY without a range leaves an opening's wall free: a tunnel
   !> deleted before `BOUND STRESS` is excavated, not held by the in-situ
   !> stress. Each loop of the free surface is walked as the loads follow it
   !> (the next corner of a loaded side, a T-junction, a joint mouth's
   !> partner, a bridged stretch) and its signed area decides: block edges
   !> run clockwise, so the outer boundary is walked clockwise (area < 0)
   !> and an opening's wall counter-clockwise (area > 0). A loop that cannot
   !> be followed round counts as outer (loaded, as before).
   subroutine boundary_opening_points(bnd, geo, grid, opening)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      logical, intent(out) :: opening(:)
      integer(ip), allocatable :: loop(:)
      logical, allocatable :: done(:)
      integer(ip) :: i, k, c, q, n, steps
      real(wp) :: area
      integer(ip) :: t
      logical :: fp, fn, closed
      opening = .false.
      if (bnd%n == 0) return
      allocate (done(bnd%n), loop(bnd%n + 1))
      done = .false.
      do i = 1, bnd%n
         if (done(i)) cycle
         c = bnd%corner(i)
         if (.not. geo%corners%live(c)) cycle
         if (.not. geo%blocks%live(geo%corners%block(c))) cycle
         n = 0
         area = 0.0_wp
         closed = .false.
         do steps = 1, bnd%n + 1
            k = boundary_index(bnd, c)
            if (k == 0) exit
            if (done(k)) exit
            done(k) = .true.
            n = n + 1
            loop(n) = k
            ! the next point along the free surface
            call loaded_sides(bnd, geo, grid, c, fp, fn)
            q = 0
            if (fn) then
               t = t_junction(bnd, geo, grid, c, .true.)
               q = merge(t, geo%corners%next(c), t > 0)
            else if (fp) then
               q = nearest_partner(bnd, geo, grid, c, .true., mouth_rules)
            end if
            if (q == 0) exit
            area = area + 0.5_wp*(geo%corners%x(c)*geo%corners%y(q) - geo%corners%x(q)*geo%corners%y(c))
            c = q
            if (c == bnd%corner(i)) then
               closed = .true.
               exit
            end if
         end do
         if (closed .and. area > 0.0_wp) opening(loop(1:n)) = .true.
      end do
   end subroutine boundary_opening_points

   !> BOUNDARY CORNER ic1 ic2: the boundary points met walking the boundary
   !> clockwise (each block's edges in their own clockwise order, crossing to
   !> a coincident corner of the next block where the free surface passes to
   !> it) from ic1 to ic2, both included. `sel(k)` marks list entry k.
   subroutine boundary_walk(bnd, geo, grid, c1, c2, sel, error)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(block_grid_t), intent(in) :: grid
      integer(ip), intent(in) :: c1, c2
      logical, intent(out) :: sel(:)
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: c, k, steps, nxt, cand
      logical :: fp, fn, found
      character(len=160) :: text
      sel = .false.
      do k = 1, 2
         c = merge(c1, c2, k == 1)
         if (boundary_index(bnd, c) == 0) then
            write (text, '(a,i0,a)') 'BOUNDARY CORNER: corner ', c, &
               ' is not a boundary point (PRINT BOUNDARY STATE lists them: ids under COR, ' // &
               '1989 addresses under ADDRESS)'
            call set_error(error, trim(text))
            return
         end if
      end do
      c = c1
      do steps = 1, 2*bnd%n + 2
         k = boundary_index(bnd, c)
         if (k > 0) sel(k) = .true.
         if (c == c2) return
         call loaded_sides(bnd, geo, grid, c, fp, fn)
         if (fn) then
            c = geo%corners%next(c)
            cycle
         end if
         ! the free surface leaves this block here: continue on the nearest
         ! boundary point of another block whose outgoing edge is free
         found = nearest_partner(bnd, geo, grid, c, .true., [partner_loaded], entry=nxt) > 0
         if (found) then
            sel(nxt) = .true.
            if (bnd%corner(nxt) == c2) return
            c = geo%corners%next(bnd%corner(nxt))
         end if
         if (.not. found) then
            cand = nearest_partner(bnd, geo, grid, c, .true., [partner_bridge])
            if (cand > 0) then
               found = .true.
               nxt = boundary_index(bnd, cand)
               sel(nxt) = .true.
               if (cand == c2) return
               c = geo%corners%next(cand)
            end if
         end if
         if (.not. found) then
            write (text, '(a,i0,a,i0,a,i0)') 'BOUNDARY CORNER: cannot follow the boundary ' // &
               'beyond corner ', c, ' (walking clockwise from corner ', c1, ' to ', c2
            call set_error(error, trim(text)//')')
            return
         end if
      end do
      write (text, '(a,i0,a,i0,a)') 'BOUNDARY CORNER: corner ', c2, &
         ' is not reached walking the boundary clockwise from corner ', c1, &
         ' (is it on another boundary loop?)'
      call set_error(error, trim(text))
   end subroutine boundary_walk

end module zones_boundary_setup
