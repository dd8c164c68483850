!> Heat conduction on the zones of fully-deformable blocks (manual Sections 7.2,
!> 7.3, 7.5.2.1): the thermal mesh, the explicit step and the Crank-Nicolson
!> step solved by Jacobi iteration, and the thermal stresses of Eq. (7-3).
!>
!> The thermal mesh is built at the start of each RUN (geometry changes are
!> ignored until the next RUN, Section 7.4.2): its nodes are the gridpoints of
!> zoned blocks, where gridpoints of different blocks closer than RUN TOL are
!> merged into one node (the joint between them conducts perfectly; never two points
!> of one block), and a
!> boundary gridpoint of one block lying on a boundary zone edge of another is
!> inserted into that edge, the zone being subdivided (Fig. 7-3). A zone split
!> on one edge is fanned from the opposite vertex; on more edges, from an extra
!> node at its centroid that lives only during the RUN.
!>
!> Per triangle the heat flow into its vertices is F = -K T with the
!> constant-gradient conductance K_ij = (kx b_i b_j + ky c_i c_j)/(4A) (the
!> gradient of Section 7.2.2, b and c the edge-normal components); the thermal
!> mass rho Cp A / 3 is lumped at each vertex. Convection, radiation and flux
!> act on edges with half the edge length per node, sources with A/3 per
!> vertex. Blocks without zones (rigid and simply-deformable) are fanned from
!> their centroid to their corners and to the contact points of other blocks'
!> corners on their edges (Fig. 7-4); a rigid block's temperature induces no
!> stress, a simply-deformable block's adds Eq. (7-3) to its uniform stress.
module thermal_conduction
   use core_sort, only: sort_order, lower_bound
   use core_union_find, only: union_find_root, union_find_join
   use core_arrays, only: grow_double
   use core_kinds, only: wp, ip
   use model_properties, only: prop_bulk, prop_density, prop_specheat, prop_thexp, prop_xcond, &
                                 prop_ycond
   use core_error, only: error_t, set_error
   use model_state, only: model_t
   use model_geometry, only: unzoned_block
   use model_thermal, only: thermal_t, thermal_size, thermal_size_rigid, bc_convection, bc_flux, bc_radiation, &
                            bc_source
   implicit none
   private
   public :: thermal_work_t, thermal_build, thermal_flows, thermal_explicit_step
   public :: thermal_implicit_step, thermal_store, thermal_apply_stress, thermal_auto_dt

   !> The thermal mesh of one RUN.
   type :: thermal_work_t
      integer(ip) :: nnode = 0, ntri = 0, nedge = 0
      integer(ip) :: ng = 0, nc = 0                    !< points: gridpoints, then corners
                                                       !< and centroids of blocks without zones
      integer(ip), allocatable :: node_of_gp(:)        !< (ng + nc + nb) node of each point;
                                                       !< 0: not in the mesh
      real(wp), allocatable :: t(:), acc(:), mass(:), diag(:), rowabs(:)
      real(wp), allocatable :: dtemp(:), q0(:), q1(:), tt(:)
      logical, allocatable :: fixed(:)
      integer(ip), allocatable :: tri(:, :)            !< (3, ntri) nodes
      real(wp), allocatable :: kt(:, :)                !< (6, ntri): k11 k22 k33 k12 k23 k13
      real(wp), allocatable :: tri_area(:)
      integer(ip), allocatable :: tri_block(:)
      integer(ip), allocatable :: edge_n(:, :), edge_kind(:)
      real(wp), allocatable :: edge_half(:), edge_p1(:), edge_p2(:), edge_t0(:)
      real(wp), allocatable :: block_source(:)         !< per block, at the current time
      integer(ip), allocatable :: src_rec(:)           !< THAPP SOURCE records
   end type thermal_work_t

contains

   !> Merge the boundary points of different blocks lying within tol of each
   !> other into one node (bp(1:nb) sorted by x, bx their x): the pairs are
   !> joined closest first, and a pair whose nodes already hold points of a
   !> same block is left apart, so a node never holds two points of one
   !> block. Joined blindly, a gridpoint within tol of another block's joint
   !> point (zones of about twice tol along the joint: RUN's default TOL 0.1
   !> under GEN EDGE 0.2) chained across the joint to its own block's next
   !> point and short-circuited the conduction along the zone edge between
   !> them (a 1-D wall across a joint: the far face 2 % too warm).
   subroutine merge_coincident(nb, bp, bx, ptx, pty, ptblk, tol, parent)
      integer(ip), intent(in) :: nb, bp(:), ptblk(:)
      real(wp), intent(in) :: bx(:), ptx(:), pty(:), tol
      integer(ip), intent(inout) :: parent(:)
      integer(ip) :: i, j, k, np, ra, rb, a, b
      integer(ip), allocatable :: pi(:), pj(:), order(:), nxt(:), last(:)
      real(wp), allocatable :: d(:)
      real(wp) :: dij
      np = 0
      allocate (pi(16), pj(16), d(16))
      do i = 1, nb
         do j = i + 1, nb
            if (bx(j) - bx(i) > tol) exit
            if (ptblk(bp(i)) == ptblk(bp(j))) cycle
            dij = hypot(ptx(bp(i)) - ptx(bp(j)), pty(bp(i)) - pty(bp(j)))
            if (dij > tol) cycle
            if (np == size(pi)) then
               call grow_double(pi)
               call grow_double(pj)
               call grow_double(d)
            end if
            np = np + 1
            pi(np) = bp(i); pj(np) = bp(j); d(np) = dij
         end do
      end do
      if (np == 0) return
      allocate (order(np), nxt(size(parent)), last(size(parent)))
      call sort_order(d(1:np), order)
      ! members of each set as a chain from its root: nxt, the root's last
      nxt = 0
      do i = 1, size(parent)
         last(i) = i
      end do
      do k = 1, np
         ra = union_find_root(parent, pi(order(k)))
         rb = union_find_root(parent, pj(order(k)))
         if (ra == rb) cycle
         if (share_block(ra, rb)) cycle
         a = min(ra, rb); b = max(ra, rb)
         call union_find_join(parent, a, b)
         nxt(last(a)) = b
         last(a) = last(b)
      end do
   contains
      logical function share_block(r1, r2) result(yes)
         integer(ip), intent(in) :: r1, r2
         integer(ip) :: p1, p2
         yes = .true.
         p1 = r1
         do while (p1 /= 0)
            p2 = r2
            do while (p2 /= 0)
               if (ptblk(p1) == ptblk(p2)) return
               p2 = nxt(p2)
            end do
            p1 = nxt(p1)
         end do
         yes = .false.
      end function share_block
   end subroutine merge_coincident

   !> Build the thermal mesh: the zones of the zoned blocks and the centroid
   !> triangles of the blocks without zones (rigid and SDEF, Fig. 7-4).
   !> Thermal points are numbered gridpoints 1..ng, then corners ng+1..ng+nc
   !> (of blocks without zones), then block centroids ng+nc+1..ng+nc+nb.
   subroutine thermal_build(model, tol, w, error)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: tol
      type(thermal_work_t), intent(out) :: w
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: ng, g, nb, i, j, z, b, mat, k, nroot, npt, nco, nbl, p
      integer(ip), allocatable :: parent(:), bgp(:), order(:), root_node(:), ptblk(:)
      real(wp), allocatable :: bx(:), ptx(:), pty(:)
      logical, allocatable :: inpt(:)
      real(wp) :: rho, cp, kx, ky
      character(len=160) :: text
      associate (gp => model%geometry%gridpoints, zn => model%geometry%zones, &
                 bl => model%geometry%blocks, co => model%geometry%corners, th => model%thermal)
         ng = gp%n
         nco = co%n
         nbl = bl%n
         call thermal_size(th, ng)
         call thermal_size_rigid(th, nco, nbl)
         npt = ng + nco + nbl
         w%ng = ng
         w%nc = nco
         allocate (parent(npt), w%node_of_gp(npt), ptx(npt), pty(npt), ptblk(npt), inpt(npt))
         w%node_of_gp = 0
         inpt = .false.
         ptx = 0.0_wp
         pty = 0.0_wp
         ptblk = 0
         do p = 1, npt
            parent(p) = p
         end do
         do g = 1, ng
            inpt(g) = in_mesh(g)
            ptx(g) = gp%x(g); pty(g) = gp%y(g); ptblk(g) = gp%block(g)
         end do
         do i = 1, nco
            if (.not. co%live(i)) cycle
            b = co%block(i)
            if (.not. unzoned_block(model%geometry, b)) cycle
            inpt(ng + i) = .true.
            ptx(ng + i) = co%x(i); pty(ng + i) = co%y(i); ptblk(ng + i) = b
         end do
         do b = 1, nbl
            if (.not. unzoned_block(model%geometry, b)) cycle
            inpt(ng + nco + b) = .true.
            ptx(ng + nco + b) = bl%xc(b); pty(ng + nco + b) = bl%yc(b)
            ptblk(ng + nco + b) = b
         end do
         ! boundary points (gridpoints on a block's boundary, corners of blocks
         ! without zones), sorted by x
         nb = 0
         allocate (bgp(ng + nco))
         do p = 1, ng + nco
            if (.not. inpt(p)) cycle
            if (p <= ng) then
               if (gp%corner(p) == 0) cycle
            end if
            nb = nb + 1
            bgp(nb) = p
         end do
         allocate (bx(nb), order(nb))
         bx = ptx(bgp(1:nb))
         call sort_order(bx, order)
         bgp(1:nb) = bgp(order)
         bx = bx(order)
         call merge_coincident(nb, bgp, bx, ptx, pty, ptblk, tol, parent)
         ! node numbers
         allocate (root_node(npt))
         root_node = 0
         nroot = 0
         do p = 1, npt
            if (.not. inpt(p)) cycle
            k = union_find_root(parent, p)
            if (root_node(k) == 0) then
               nroot = nroot + 1
               root_node(k) = nroot
            end if
            w%node_of_gp(p) = root_node(k)
         end do
         w%nnode = nroot
         ! node temperatures: mean of the points (fixed ones win)
         allocate (w%t(nroot + 64), w%acc(nroot + 64), w%fixed(nroot + 64), w%mass(nroot + 64))
         w%t = 0.0_wp
         w%acc = 0.0_wp
         w%fixed = .false.
         w%mass = 0.0_wp     ! used as a counter here
         do p = 1, npt
            k = w%node_of_gp(p)
            if (k == 0) cycle
            if (pt_fixed(p)) then
               if (.not. w%fixed(k)) then
                  w%t(k) = 0.0_wp
                  w%acc(k) = 0.0_wp
                  w%mass(k) = 0.0_wp
               end if
               w%fixed(k) = .true.
            else if (w%fixed(k)) then
               cycle
            end if
            w%t(k) = w%t(k) + pt_value(p, 1)
            w%acc(k) = w%acc(k) + pt_value(p, 2)
            w%mass(k) = w%mass(k) + 1.0_wp
         end do
         do k = 1, nroot
            if (w%mass(k) > 0.0_wp) then
               w%t(k) = w%t(k)/w%mass(k)
               w%acc(k) = w%acc(k)/w%mass(k)
            end if
         end do
         w%mass = 0.0_wp
         ! triangles (zones, subdivided where foreign points lie on their edges;
         ! centroid fans of the blocks without zones)
         allocate (w%tri(3, 2*zn%n + 4*nco + 16), w%kt(6, 2*zn%n + 4*nco + 16), &
                   w%tri_area(2*zn%n + 4*nco + 16), w%tri_block(2*zn%n + 4*nco + 16))
         w%ntri = 0
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            b = zn%block(z)
            if (.not. bl%live(b)) cycle
            if (.not. block_props(b)) return
            call add_zone(z, rho*cp, kx, ky)
         end do
         do b = 1, nbl
            if (.not. unzoned_block(model%geometry, b)) cycle
            if (.not. block_props(b)) return
            call add_block(b, rho*cp, kx, ky)
            if (allocated(error)) return
         end do
         call build_edges()
         allocate (w%block_source(bl%n))
         w%block_source = 0.0_wp
         allocate (w%src_rec(0))
         if (th%nrec > 0) w%src_rec = pack([(i, i=1, th%nrec)], &
                                           th%rec_kind(1:th%nrec) == bc_source)
         allocate (w%dtemp(w%nnode), w%q0(w%nnode), w%q1(w%nnode), w%tt(w%nnode))
         call row_sums()
      end associate

   contains

      !> Thermal properties of block bb into rho, cp, kx, ky; false (and the
      !> error set) when DENSITY or SPECHEAT is missing.
      logical function block_props(bb) result(ok)
         integer(ip), intent(in) :: bb
         integer(ip) :: m
         m = model%geometry%blocks%material(bb)
         rho = model%materials%get(m, prop_density)
         cp = model%materials%get(m, prop_specheat)
         kx = model%materials%get(m, prop_xcond)
         ky = model%materials%get(m, prop_ycond)
         mat = m
         ok = rho > 0.0_wp .and. cp > 0.0_wp
         if (.not. ok) then
            write (text, '(a,i0,a,i0,a)') 'RUN: material ', m, ' of block ', bb, &
               ' needs DENSITY and SPECHEAT > 0 for the thermal calculation (PROPERTY)'
            call set_error(error, trim(text))
         end if
      end function block_props

      logical function pt_fixed(pp)
         integer(ip), intent(in) :: pp
         if (pp <= ng) then
            pt_fixed = model%thermal%fixed(pp)
         else if (pp <= ng + nco) then
            pt_fixed = model%thermal%cfixed(pp - ng)
         else
            pt_fixed = model%thermal%bfixed(pp - ng - nco)
         end if
      end function pt_fixed

      !> Temperature (which 1) or accumulated change (which 2) of point pp.
      real(wp) function pt_value(pp, which)
         integer(ip), intent(in) :: pp
         integer, intent(in) :: which
         associate (t => model%thermal)
            if (pp <= ng) then
               pt_value = merge(t%temp(pp), t%dtacc(pp), which == 1)
            else if (pp <= ng + nco) then
               pt_value = merge(t%ctemp(pp - ng), t%cdtacc(pp - ng), which == 1)
            else
               pt_value = merge(t%btemp(pp - ng - nco), t%bdtacc(pp - ng - nco), which == 1)
            end if
         end associate
      end function pt_value

      logical function in_mesh(g)
         integer(ip), intent(in) :: g
         integer(ip) :: bb
         in_mesh = .false.
         if (.not. model%geometry%gridpoints%live(g)) return
         bb = model%geometry%gridpoints%block(g)
         if (bb < 1) return
         if (.not. model%geometry%blocks%live(bb)) return
         in_mesh = model%geometry%blocks%nzone(bb) > 0
      end function in_mesh

      !> Point pp lies on the edge (xa, ya)-(xc, yc): within tol of it, and
      !> farther than tol from both its ends (a point that near an end is
      !> merged with it or, being a neighbour of the same block, kept apart:
      !> inserting it, or a point a rounding error short of an end, joined
      !> the blocks' neighbouring points through the edge); s: where along it.
      logical function on_edge(pp, xa, ya, xc, yc, s) result(yes)
         integer(ip), intent(in) :: pp
         real(wp), intent(in) :: xa, ya, xc, yc
         real(wp), intent(out) :: s
         real(wp) :: ex, ey, len2
         yes = .false.
         ex = xc - xa; ey = yc - ya
         len2 = ex*ex + ey*ey
         s = ((ptx(pp) - xa)*ex + (pty(pp) - ya)*ey)/len2
         if (s <= 0.0_wp .or. s >= 1.0_wp) return
         if (hypot(ptx(pp) - xa, pty(pp) - ya) <= tol) return
         if (hypot(ptx(pp) - xc, pty(pp) - yc) <= tol) return
         yes = abs((ptx(pp) - xa)*ey - (pty(pp) - ya)*ex)/sqrt(len2) <= tol
      end function on_edge

      !> Foreign boundary points on the edges of zone z, then its triangles.
      subroutine add_zone(zz, rhocp, kxx, kyy)
         integer(ip), intent(in) :: zz
         real(wp), intent(in) :: rhocp, kxx, kyy
         integer(ip) :: v(3), nv(3), e, a, c, lo, m, p, np, nedges_hit, apex, cnode
         integer(ip) :: pn(64), ecount(3), ii, jj, perm(64)
         real(wp) :: px(64), py(64), ps(64), xa, ya, xc, yc, dx, dy, len2, s, xm, ym
         associate (gp => model%geometry%gridpoints, zn => model%geometry%zones)
            v = [zn%g1(zz), zn%g2(zz), zn%g3(zz)]
            nv = w%node_of_gp(v)
            np = 0
            ecount = 0
            do e = 1, 3
               a = v(e)
               c = v(mod(e, 3) + 1)
               ! the edge's own vertex starts its run of polygon points
               np = np + 1
               pn(np) = nv(e); px(np) = gp%x(a); py(np) = gp%y(a); ps(np) = -1.0_wp
               if (gp%corner(a) == 0 .or. gp%corner(c) == 0) cycle
               xa = gp%x(a); ya = gp%y(a); xc = gp%x(c); yc = gp%y(c)
               dx = xc - xa; dy = yc - ya
               len2 = dx*dx + dy*dy
               if (len2 <= 0.0_wp) cycle
               lo = bx_lower_bound(min(xa, xc) - tol)
               lo = max(lo, 1_ip)
               m = np
               do i = lo, nb
                  if (bx(i) > max(xa, xc) + tol) exit
                  p = bgp(i)
                  if (ptblk(p) == zn%block(zz)) cycle
                  if (w%node_of_gp(p) == nv(e) .or. &
                      w%node_of_gp(p) == nv(mod(e, 3) + 1)) cycle
                  if (.not. on_edge(p, xa, ya, xc, yc, s)) cycle
                  if (any(pn(m + 1:np) == w%node_of_gp(p))) cycle
                  if (np >= 63) exit
                  np = np + 1
                  pn(np) = w%node_of_gp(p)
                  px(np) = xa + s*dx; py(np) = ya + s*dy
                  ps(np) = s
               end do
               ecount(e) = np - m
               ! order the inserted points along the edge
               call order_along_edge(pn(m + 1:np), px(m + 1:np), py(m + 1:np), ps(m + 1:np), &
                                     perm(1:np - m))
            end do
            nedges_hit = count(ecount > 0)
            if (nedges_hit == 0) then
               call add_triangle(nv(1), nv(2), nv(3), gp%x(v), gp%y(v), rhocp, kxx, kyy, zn%block(zz))
            else if (nedges_hit == 1) then
               ! fan from the vertex opposite the split edge
               e = maxloc(ecount, 1)
               apex = mod(e + 1, 3) + 1
               xm = gp%x(v(apex)); ym = gp%y(v(apex))
               cnode = nv(apex)
            else
               cnode = new_node()
               xm = sum(gp%x(v))/3.0_wp; ym = sum(gp%y(v))/3.0_wp
               w%t(cnode) = sum(w%t(nv))/3.0_wp
               w%acc(cnode) = sum(w%acc(nv))/3.0_wp
            end if
            if (nedges_hit > 0) then
               ! fan from cnode over the polygon's sides (skipping those at the apex)
               do ii = 1, np
                  jj = mod(ii, np) + 1
                  if (pn(ii) == cnode .or. pn(jj) == cnode) cycle
                  call add_triangle(cnode, pn(ii), pn(jj), [xm, px(ii), px(jj)], &
                                    [ym, py(ii), py(jj)], rhocp, kxx, kyy, zn%block(zz))
               end do
            end if
         end associate
      end subroutine add_zone

      !> Fig. 7-4: a block without zones is fanned from its centroid to its
      !> corners and to the foreign boundary points (corners or gridpoints of
      !> other blocks) lying on its edges within tol. Where a fan triangle
      !> would turn the wrong way (the centroid outside the block's kernel)
      !> the block is cut into ears instead (add_ears).
      subroutine add_block(bb, rhocp, kxx, kyy)
         integer(ip), intent(in) :: bb
         real(wp), intent(in) :: rhocp, kxx, kyy
         integer(ip) :: c, cn, kk, lo, m, pp, np, cnode, ii, jj, na, nc2, i
         integer(ip), allocatable :: pn(:), perm(:)
         real(wp), allocatable :: px(:), py(:), ps(:)
         real(wp) :: xa, ya, xc, yc, dx, dy, len2, s, xm, ym, a2, orient
         associate (co => model%geometry%corners, bl => model%geometry%blocks)
            nc2 = bl%ncorner(bb)
            allocate (pn(nc2 + 16), px(nc2 + 16), py(nc2 + 16), ps(nc2 + 16), perm(nc2 + 16))
            np = 0
            c = bl%first_corner(bb)
            do kk = 1, nc2
               cn = co%next(c)
               if (np >= size(pn)) then
                  call grow_double(pn); call grow_double(px); call grow_double(py)
                  call grow_double(ps); call grow_double(perm)
               end if
               np = np + 1
               pn(np) = w%node_of_gp(ng + c); px(np) = co%x(c); py(np) = co%y(c); ps(np) = -1.0_wp
               xa = co%x(c); ya = co%y(c); xc = co%x(cn); yc = co%y(cn)
               dx = xc - xa; dy = yc - ya
               len2 = dx*dx + dy*dy
               m = np
               if (len2 > 0.0_wp) then
                  lo = max(bx_lower_bound(min(xa, xc) - tol), 1_ip)
                  do i = lo, nb
                     if (bx(i) > max(xa, xc) + tol) exit
                     pp = bgp(i)
                     if (ptblk(pp) == bb) cycle
                     if (w%node_of_gp(pp) == w%node_of_gp(ng + c) .or. &
                         w%node_of_gp(pp) == w%node_of_gp(ng + cn)) cycle
                     if (.not. on_edge(pp, xa, ya, xc, yc, s)) cycle
                     if (any(pn(m + 1:np) == w%node_of_gp(pp))) cycle
                     if (np >= size(pn)) then
                        call grow_double(pn); call grow_double(px); call grow_double(py)
                        call grow_double(ps); call grow_double(perm)
                     end if
                     np = np + 1
                     pn(np) = w%node_of_gp(pp); px(np) = xa + s*dx; py(np) = ya + s*dy; ps(np) = s
                  end do
                  call order_along_edge(pn(m + 1:np), px(m + 1:np), py(m + 1:np), ps(m + 1:np), &
                                        perm(1:np - m))
               end if
               c = cn
            end do
            cnode = w%node_of_gp(ng + nco + bb)
            xm = bl%xc(bb); ym = bl%yc(bb)
            ! orientation of the polygon (shoelace), then each fan triangle
            a2 = 0.0_wp
            do ii = 1, np
               jj = mod(ii, np) + 1
               a2 = a2 + px(ii)*py(jj) - px(jj)*py(ii)
            end do
            orient = sign(1.0_wp, a2)
            ! a centroid that does not see all the edges (a block around a
            ! TUNNEL, a U shape): the polygon is cut into ears instead
            do ii = 1, np
               jj = mod(ii, np) + 1
               if (pn(ii) == pn(jj)) cycle
               a2 = (px(ii) - xm)*(py(jj) - ym) - (px(jj) - xm)*(py(ii) - ym)
               if (orient*a2 < -1.0e-12_wp*abs(bl%area(bb))) then
                  call add_ears(bb, np, pn, px, py, orient, cnode, xm, ym, rhocp, kxx, kyy)
                  return
               end if
            end do
            na = 0
            do ii = 1, np
               jj = mod(ii, np) + 1
               if (pn(ii) == pn(jj)) cycle
               if (orient > 0.0_wp) then
                  call add_triangle(cnode, pn(ii), pn(jj), [xm, px(ii), px(jj)], &
                                    [ym, py(ii), py(jj)], rhocp, kxx, kyy, bb)
               else
                  call add_triangle(cnode, pn(jj), pn(ii), [xm, px(jj), px(ii)], &
                                    [ym, py(jj), py(ii)], rhocp, kxx, kyy, bb)
               end if
               na = na + 1
            end do
         end associate
      end subroutine add_block

      !> A block without zones whose centroid does not see all its edges:
      !> its boundary polygon (np points, nodes pn, orientation orient) is
      !> cut into ears (triangles of three consecutive points, convex, no
      !> other point in or on them); the ear that holds the centroid
      !> strictly is fanned from it, so the centroid node keeps its share of
      !> the block. A centroid outside the block (a C shape) takes no
      !> triangle: that node has no thermal mass and keeps its temperature.
      !> Where no ear is left (a degenerate polygon), RUN refuses the block.
      subroutine add_ears(bb, np, pn, px, py, orient, cnode, xm, ym, rhocp, kxx, kyy)
         integer(ip), intent(in) :: bb, np, pn(:), cnode
         real(wp), intent(in) :: px(:), py(:), orient, xm, ym, rhocp, kxx, kyy
         integer(ip), allocatable :: v(:), tri(:, :)
         integer(ip) :: m, nt, i, ia, ib, ic, k, t, hold
         real(wp) :: eps, cr
         logical :: ear
         eps = 1.0e-12_wp*abs(model%geometry%blocks%area(bb))
         ! counter-clockwise list of the points, repeated nodes dropped
         allocate (v(np), tri(3, np))
         m = 0
         do i = 1, np
            k = merge(i, np + 1 - i, orient > 0.0_wp)
            if (m > 0) then
               if (pn(v(m)) == pn(k)) cycle
            end if
            m = m + 1
            v(m) = k
         end do
         if (m > 1) then
            if (pn(v(m)) == pn(v(1))) m = m - 1
         end if
         nt = 0
         do while (m > 3)
            ear = .false.
            do i = 1, m
               ia = v(mod(i + m - 2, m) + 1); ib = v(i); ic = v(mod(i, m) + 1)
               cr = (px(ib) - px(ia))*(py(ic) - py(ib)) - (py(ib) - py(ia))*(px(ic) - px(ib))
               if (cr <= eps) cycle
               ear = .true.
               do k = 1, m
                  t = v(k)
                  if (t == ia .or. t == ib .or. t == ic) cycle
                  if (pn(t) == pn(ia) .or. pn(t) == pn(ib) .or. pn(t) == pn(ic)) cycle
                  if (inside_triangle(px(t), py(t), px(ia), py(ia), px(ib), py(ib), px(ic), py(ic), &
                                      -eps)) then
                     ear = .false.
                     exit
                  end if
               end do
               if (.not. ear) cycle
               nt = nt + 1
               tri(:, nt) = [ia, ib, ic]
               v(i:m - 1) = v(i + 1:m)
               m = m - 1
               exit
            end do
            if (.not. ear) then
               write (text, '(a,i0,a)') 'RUN: block ', bb, ' has no zones and its '// &
                  'boundary cannot be cut into triangles (Fig. 7-4): zone it (GENERATE) or split it'
               call set_error(error, trim(text))
               return
            end if
         end do
         ia = v(1); ib = v(2); ic = v(3)
         if (m == 3 .and. (px(ib) - px(ia))*(py(ic) - py(ib)) - (py(ib) - py(ia))*(px(ic) - px(ib)) > eps) then
            nt = nt + 1
            tri(:, nt) = [ia, ib, ic]
         end if
         hold = 0
         do t = 1, nt
            if (inside_triangle(xm, ym, px(tri(1, t)), py(tri(1, t)), px(tri(2, t)), py(tri(2, t)), &
                                px(tri(3, t)), py(tri(3, t)), eps)) then
               hold = t
               exit
            end if
         end do
         do t = 1, nt
            ia = tri(1, t); ib = tri(2, t); ic = tri(3, t)
            if (t == hold) then
               call add_triangle(cnode, pn(ia), pn(ib), [xm, px(ia), px(ib)], [ym, py(ia), py(ib)], &
                                 rhocp, kxx, kyy, bb)
               call add_triangle(cnode, pn(ib), pn(ic), [xm, px(ib), px(ic)], [ym, py(ib), py(ic)], &
                                 rhocp, kxx, kyy, bb)
               call add_triangle(cnode, pn(ic), pn(ia), [xm, px(ic), px(ia)], [ym, py(ic), py(ia)], &
                                 rhocp, kxx, kyy, bb)
            else
               call add_triangle(pn(ia), pn(ib), pn(ic), [px(ia), px(ib), px(ic)], &
                                 [py(ia), py(ib), py(ic)], rhocp, kxx, kyy, bb)
            end if
         end do
      end subroutine add_ears

      !> Point (x, y) left of each edge of the counter-clockwise triangle
      !> a, b, c by more than `tol` (tol < 0: in or on it; tol > 0:
      !> strictly inside).
      logical function inside_triangle(x, y, xa, ya, xb, yb, xc, yc, tol) result(yes)
         real(wp), intent(in) :: x, y, xa, ya, xb, yb, xc, yc, tol
         yes = (xb - xa)*(y - ya) - (yb - ya)*(x - xa) > tol .and. &
               (xc - xb)*(y - yb) - (yc - yb)*(x - xb) > tol .and. &
               (xa - xc)*(y - yc) - (ya - yc)*(x - xc) > tol
      end function inside_triangle

      integer(ip) function bx_lower_bound(x) result(lo)
         real(wp), intent(in) :: x
         lo = lower_bound(bx(1:nb), x)
      end function bx_lower_bound

      integer(ip) function new_node() result(k)
         if (w%nnode >= size(w%t)) then
            call grow_double(w%t); call grow_double(w%acc); call grow_double(w%mass)
            call grow_double(w%fixed)
         end if
         w%nnode = w%nnode + 1
         k = w%nnode
         w%t(k) = 0.0_wp
         w%acc(k) = 0.0_wp
         w%mass(k) = 0.0_wp
         w%fixed(k) = .false.
      end function new_node

      subroutine add_triangle(n1, n2, n3, x, y, rhocp, kxx, kyy, blk)
         integer(ip), intent(in) :: n1, n2, n3, blk
         real(wp), intent(in) :: x(3), y(3), rhocp, kxx, kyy
         real(wp) :: bb(3), cc(3), area
         integer(ip) :: t
         real(wp), allocatable :: r2(:, :)
         integer(ip), allocatable :: i2(:, :)
         bb = [y(2) - y(3), y(3) - y(1), y(1) - y(2)]
         cc = [x(3) - x(2), x(1) - x(3), x(2) - x(1)]
         area = 0.5_wp*(bb(1)*cc(2) - bb(2)*cc(1))
         if (area <= 0.0_wp) return
         if (w%ntri >= size(w%tri_area)) then
            allocate (i2(3, 2*size(w%tri_area)), r2(6, 2*size(w%tri_area)))
            i2(:, 1:w%ntri) = w%tri(:, 1:w%ntri)
            r2(:, 1:w%ntri) = w%kt(:, 1:w%ntri)
            call move_alloc(i2, w%tri)
            call move_alloc(r2, w%kt)
            call grow_double(w%tri_area)
            call grow_double(w%tri_block)
         end if
         w%ntri = w%ntri + 1
         t = w%ntri
         w%tri(:, t) = [n1, n2, n3]
         w%kt(1, t) = (kxx*bb(1)*bb(1) + kyy*cc(1)*cc(1))/(4.0_wp*area)
         w%kt(2, t) = (kxx*bb(2)*bb(2) + kyy*cc(2)*cc(2))/(4.0_wp*area)
         w%kt(3, t) = (kxx*bb(3)*bb(3) + kyy*cc(3)*cc(3))/(4.0_wp*area)
         w%kt(4, t) = (kxx*bb(1)*bb(2) + kyy*cc(1)*cc(2))/(4.0_wp*area)
         w%kt(5, t) = (kxx*bb(2)*bb(3) + kyy*cc(2)*cc(3))/(4.0_wp*area)
         w%kt(6, t) = (kxx*bb(1)*bb(3) + kyy*cc(1)*cc(3))/(4.0_wp*area)
         w%tri_area(t) = area
         w%tri_block(t) = blk
         w%mass([n1, n2, n3]) = w%mass([n1, n2, n3]) + rhocp*area/3.0_wp
      end subroutine add_triangle

      !> Edges carrying convection, radiation or flux: consecutive corners of a
      !> block that both hold a record of one THAPP command.
      subroutine build_edges()
         integer(ip) :: c, cn, r, r2, n1, n2, nc
         integer(ip), allocatable :: head(:), next_rec(:)
         associate (co => model%geometry%corners, th => model%thermal)
            nc = co%n
            allocate (head(nc), next_rec(max(th%nrec, 1)))
            head = 0
            do r = th%nrec, 1, -1
               if (th%rec_kind(r) == bc_source) cycle
               c = th%rec_id(r)
               if (c < 1 .or. c > nc) cycle
               next_rec(r) = head(c)
               head(c) = r
            end do
            allocate (w%edge_n(2, 16), w%edge_kind(16), w%edge_half(16), w%edge_p1(16), &
                      w%edge_p2(16), w%edge_t0(16))
            w%nedge = 0
            do c = 1, nc
               if (.not. co%live(c)) cycle
               if (.not. model%geometry%blocks%live(co%block(c))) cycle
               cn = co%next(c)
               if (cn < 1) cycle
               n1 = corner_node(c)
               n2 = corner_node(cn)
               if (n1 == 0 .or. n2 == 0) cycle
               r = head(c)
               do while (r > 0)
                  r2 = head(cn)
                  do while (r2 > 0)
                     if (th%rec_set(r2) == th%rec_set(r)) then
                        call add_edge(n1, n2, 0.5_wp*hypot(co%x(cn) - co%x(c), &
                                                         co%y(cn) - co%y(c)), r)
                        exit
                     end if
                     r2 = next_rec(r2)
                  end do
                  r = next_rec(r)
               end do
            end do
         end associate
      end subroutine build_edges

      !> Thermal node of corner cc: its gridpoint's (zoned block) or its own.
      integer(ip) function corner_node(cc) result(k)
         integer(ip), intent(in) :: cc
         integer(ip) :: gg
         k = 0
         gg = model%geometry%corners%gp(cc)
         if (gg > 0) then
            if (gg <= ng) k = w%node_of_gp(gg)
         else if (cc <= nco) then
            k = w%node_of_gp(ng + cc)
         end if
      end function corner_node

      subroutine add_edge(n1, n2, half, r)
         integer(ip), intent(in) :: n1, n2, r
         real(wp), intent(in) :: half
         integer(ip), allocatable :: i2(:, :)
         integer(ip) :: e
         if (w%nedge >= size(w%edge_kind)) then
            ! the same capacity grow_i and grow give the other edge arrays
            allocate (i2(2, 2*size(w%edge_kind) + 16))
            i2(:, 1:w%nedge) = w%edge_n(:, 1:w%nedge)
            call move_alloc(i2, w%edge_n)
            call grow_double(w%edge_kind)
            call grow_double(w%edge_half); call grow_double(w%edge_p1); call grow_double(w%edge_p2)
            call grow_double(w%edge_t0)
         end if
         w%nedge = w%nedge + 1
         e = w%nedge
         w%edge_n(:, e) = [n1, n2]
         w%edge_kind(e) = model%thermal%rec_kind(r)
         w%edge_half(e) = half
         w%edge_p1(e) = model%thermal%rec_p1(r)
         w%edge_p2(e) = model%thermal%rec_p2(r)
         w%edge_t0(e) = model%thermal%rec_t0(r)
      end subroutine add_edge

      !> Diagonal of the conductance (with convection) and the absolute row sums
      !> (Gershgorin bound of the explicit stability limit).
      subroutine row_sums()
         integer(ip) :: t, e, n1, n2, n3
         allocate (w%diag(w%nnode), w%rowabs(w%nnode))
         w%diag = 0.0_wp
         w%rowabs = 0.0_wp
         do t = 1, w%ntri
            n1 = w%tri(1, t); n2 = w%tri(2, t); n3 = w%tri(3, t)
            w%diag(n1) = w%diag(n1) + w%kt(1, t)
            w%diag(n2) = w%diag(n2) + w%kt(2, t)
            w%diag(n3) = w%diag(n3) + w%kt(3, t)
            w%rowabs(n1) = w%rowabs(n1) + abs(w%kt(1, t)) + abs(w%kt(4, t)) + abs(w%kt(6, t))
            w%rowabs(n2) = w%rowabs(n2) + abs(w%kt(2, t)) + abs(w%kt(4, t)) + abs(w%kt(5, t))
            w%rowabs(n3) = w%rowabs(n3) + abs(w%kt(3, t)) + abs(w%kt(5, t)) + abs(w%kt(6, t))
         end do
         do e = 1, w%nedge
            if (w%edge_kind(e) /= bc_convection) cycle
            n1 = w%edge_n(1, e); n2 = w%edge_n(2, e)
            w%diag(n1) = w%diag(n1) + w%edge_p1(e)*w%edge_half(e)
            w%diag(n2) = w%diag(n2) + w%edge_p1(e)*w%edge_half(e)
            w%rowabs(n1) = w%rowabs(n1) + abs(w%edge_p1(e))*w%edge_half(e)
            w%rowabs(n2) = w%rowabs(n2) + abs(w%edge_p1(e))*w%edge_half(e)
         end do
      end subroutine row_sums

   end subroutine thermal_build

   !> Half the explicit stability limit (Section 7.4.1: "usually one half the
   !> critical value"): 1 / max_i (sum_j |K_ij| / M_i); 0 if nothing conducts.
   real(wp) function thermal_auto_dt(w) result(dt)
      type(thermal_work_t), intent(in) :: w
      real(wp) :: rate
      integer(ip) :: k
      rate = 0.0_wp
      do k = 1, w%nnode
         if (w%fixed(k) .or. w%mass(k) <= 0.0_wp) cycle
         rate = max(rate, w%rowabs(k)/w%mass(k))
      end do
      dt = 0.0_wp
      if (rate > 0.0_wp) dt = 1.0_wp/rate
   end function thermal_auto_dt

   !> Net heat flow q into every node for temperatures t at thermal time time.
   subroutine thermal_flows(w, th, t, time, q)
      type(thermal_work_t), intent(inout) :: w
      type(thermal_t), intent(in) :: th
      real(wp), intent(in) :: t(:), time
      real(wp), intent(out) :: q(:)
      integer(ip) :: k, e, n1, n2, n3, r
      real(wp) :: s, f
      q(1:w%nnode) = 0.0_wp
      do k = 1, w%ntri
         n1 = w%tri(1, k); n2 = w%tri(2, k); n3 = w%tri(3, k)
         q(n1) = q(n1) - (w%kt(1, k)*t(n1) + w%kt(4, k)*t(n2) + w%kt(6, k)*t(n3))
         q(n2) = q(n2) - (w%kt(4, k)*t(n1) + w%kt(2, k)*t(n2) + w%kt(5, k)*t(n3))
         q(n3) = q(n3) - (w%kt(6, k)*t(n1) + w%kt(5, k)*t(n2) + w%kt(3, k)*t(n3))
      end do
      if (size(w%src_rec) > 0) then
         w%block_source = 0.0_wp
         do k = 1, size(w%src_rec)
            r = w%src_rec(k)
            if (th%rec_id(r) < 1 .or. th%rec_id(r) > size(w%block_source)) cycle
            w%block_source(th%rec_id(r)) = w%block_source(th%rec_id(r)) + &
                                           th%rec_p1(r)*exp(th%rec_p2(r)*(time - th%rec_t0(r)))
         end do
         do k = 1, w%ntri
            s = w%block_source(w%tri_block(k))
            if (s == 0.0_wp) cycle
            f = s*w%tri_area(k)/3.0_wp
            q(w%tri(:, k)) = q(w%tri(:, k)) + f
         end do
      end if
      do e = 1, w%nedge
         n1 = w%edge_n(1, e); n2 = w%edge_n(2, e)
         select case (w%edge_kind(e))
         case (bc_convection)
            q(n1) = q(n1) + w%edge_p1(e)*w%edge_half(e)*(w%edge_p2(e) - t(n1))
            q(n2) = q(n2) + w%edge_p1(e)*w%edge_half(e)*(w%edge_p2(e) - t(n2))
         case (bc_radiation)
            q(n1) = q(n1) + w%edge_p1(e)*w%edge_half(e)*(w%edge_p2(e)**4 - t(n1)**4)
            q(n2) = q(n2) + w%edge_p1(e)*w%edge_half(e)*(w%edge_p2(e)**4 - t(n2)**4)
         case (bc_flux)
            f = w%edge_p1(e)*exp(w%edge_p2(e)*(time - w%edge_t0(e)))*w%edge_half(e)
            q(n1) = q(n1) + f
            q(n2) = q(n2) + f
         end select
      end do
   end subroutine thermal_flows

   !> One explicit step: T += dt Q / (rho Cp M) at free nodes; returns the
   !> largest accumulated change since the last mechanical cycles.
   subroutine thermal_explicit_step(w, th, dt, temmax)
      type(thermal_work_t), intent(inout) :: w
      type(thermal_t), intent(in) :: th
      real(wp), intent(in) :: dt
      real(wp), intent(out) :: temmax
      integer(ip) :: k
      real(wp) :: d
      call thermal_flows(w, th, w%t, th%time, w%q0)
      temmax = 0.0_wp
      do k = 1, w%nnode
         if (w%fixed(k) .or. w%mass(k) <= 0.0_wp) cycle
         d = dt*w%q0(k)/w%mass(k)
         w%t(k) = w%t(k) + d
         w%acc(k) = w%acc(k) + d
      end do
      temmax = maxval(abs(w%acc(1:w%nnode)))
   end subroutine thermal_explicit_step

   !> One Crank-Nicolson step (Section 7.3): (M/dt + K/2) dT = (Q(T) + Q(T+dT))/2
   !> solved matrix-free by Jacobi iteration, at least 3 iterations, until the
   !> largest correction is below 1e-7 of the largest change (or of the
   !> temperature scale). Fails when the iteration diverges or does not converge.
   subroutine thermal_implicit_step(w, th, dt, temmax, iterations, error)
      type(thermal_work_t), intent(inout) :: w
      type(thermal_t), intent(in) :: th
      real(wp), intent(in) :: dt
      real(wp), intent(out) :: temmax
      integer, intent(out) :: iterations
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: max_iterations = 20000
      integer(ip) :: k, n
      real(wp) :: corr, big, scale, prev
      logical :: diverged
      n = w%nnode
      call thermal_flows(w, th, w%t, th%time, w%q0)
      do k = 1, n
         w%dtemp(k) = 0.0_wp
         if (w%fixed(k) .or. w%mass(k) <= 0.0_wp) cycle
         w%dtemp(k) = dt*w%q0(k)/(w%mass(k) + 0.5_wp*dt*w%diag(k))
      end do
      scale = max(maxval(abs(w%t(1:n))), tiny(1.0_wp))
      prev = 0.0_wp
      iterations = 0
      do
         iterations = iterations + 1
         w%tt(1:n) = w%t(1:n) + w%dtemp(1:n)
         call thermal_flows(w, th, w%tt, th%time + dt, w%q1)
         corr = 0.0_wp
         do k = 1, n
            if (w%fixed(k) .or. w%mass(k) <= 0.0_wp) cycle
            w%q1(k) = (0.5_wp*(w%q0(k) + w%q1(k)) - w%mass(k)*w%dtemp(k)/dt)/ &
                      (w%mass(k)/dt + 0.5_wp*w%diag(k))
            corr = max(corr, abs(w%q1(k)))
         end do
         do k = 1, n
            if (w%fixed(k) .or. w%mass(k) <= 0.0_wp) cycle
            w%dtemp(k) = w%dtemp(k) + w%q1(k)
         end do
         big = maxval(abs(w%dtemp(1:n)))
         if (iterations >= 3 .and. corr <= 1.0e-7_wp*max(big, 1.0e-6_wp*scale)) exit
         diverged = corr /= corr
         if (iterations > 50) diverged = diverged .or. (corr > 10.0_wp*prev .and. corr > scale)
         if (diverged) then
            call set_error(error, 'RUN IMPLICIT: the Jacobi iteration diverges; reduce the '// &
                           'thermal time step (SET THDT or RUN DELT)')
            return
         end if
         if (iterations >= max_iterations) then
            call set_error(error, 'RUN IMPLICIT: the Jacobi iteration did not converge in '// &
                           '20000 iterations; reduce the thermal time step (SET THDT)')
            return
         end if
         prev = corr
      end do
      w%t(1:n) = w%t(1:n) + w%dtemp(1:n)
      w%acc(1:n) = w%acc(1:n) + w%dtemp(1:n)
      temmax = maxval(abs(w%acc(1:n)))
   end subroutine thermal_implicit_step

   !> Copy node temperatures and accumulated changes back to the gridpoints,
   !> and to the corners and centroids of the blocks without zones.
   subroutine thermal_store(model, w)
      type(model_t), intent(inout) :: model
      type(thermal_work_t), intent(in) :: w
      integer(ip) :: g, k, c, b
      associate (th => model%thermal)
         do g = 1, min(th%ng, w%ng)
            k = w%node_of_gp(g)
            if (k == 0) cycle
            th%temp(g) = w%t(k)
            th%dtacc(g) = w%acc(k)
         end do
         do c = 1, min(th%nc, w%nc)
            k = w%node_of_gp(w%ng + c)
            if (k == 0) cycle
            th%ctemp(c) = w%t(k)
            th%cdtacc(c) = w%acc(k)
         end do
         do b = 1, min(th%nb, size(w%node_of_gp, kind=ip) - w%ng - w%nc)
            k = w%node_of_gp(w%ng + w%nc + b)
            if (k == 0) cycle
            th%btemp(b) = w%t(k)
            th%bdtacc(b) = w%acc(k)
         end do
      end associate
   end subroutine thermal_store

   !> Thermal stresses of the accumulated temperature changes (Eq. 7-3):
   !> d sigma_ii = -K beta dT with beta = 3 alpha (THEXP) and dT the mean change
   !> at the zone's gridpoints, on sxx, syy and szz (plane strain); the
   !> accumulated changes are then cleared. A simply-deformable block takes
   !> the same increment on its uniform stress (sxx, syy), dT the mean change
   !> over its Fig. 7-4 triangles (lumped as in the conduction); a rigid block
   !> cannot deform, its temperature changes induce no stress.
   subroutine thermal_apply_stress(model)
      type(model_t), intent(inout) :: model
      integer(ip) :: z, b, mat, c, cn, k
      real(wp) :: kb, alpha, dtz, ds, a, asum, tsum
      associate (zn => model%geometry%zones, bl => model%geometry%blocks, &
                 co => model%geometry%corners, th => model%thermal)
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            b = zn%block(z)
            if (.not. bl%live(b)) cycle
            mat = bl%material(b)
            alpha = model%materials%get(mat, prop_thexp)
            kb = model%materials%get(mat, prop_bulk)
            if (alpha == 0.0_wp .or. kb <= 0.0_wp) cycle
            if (max(zn%g1(z), zn%g2(z), zn%g3(z)) > th%ng) cycle
            dtz = (th%dtacc(zn%g1(z)) + th%dtacc(zn%g2(z)) + th%dtacc(zn%g3(z)))/3.0_wp
            ds = -kb*3.0_wp*alpha*dtz
            zn%sxx(z) = zn%sxx(z) + ds
            zn%syy(z) = zn%syy(z) + ds
            zn%szz(z) = zn%szz(z) + ds
         end do
         th%dtacc(1:th%ng) = 0.0_wp
         if (allocated(bl%sdef) .and. th%nb > 0) then
            do b = 1, min(bl%n, th%nb)
               if (.not. bl%live(b)) cycle
               if (.not. bl%sdef(b) .or. bl%nzone(b) > 0) cycle
               mat = bl%material(b)
               alpha = model%materials%get(mat, prop_thexp)
               kb = model%materials%get(mat, prop_bulk)
               if (alpha == 0.0_wp .or. kb <= 0.0_wp) cycle
               asum = 0.0_wp
               tsum = 0.0_wp
               c = bl%first_corner(b)
               do k = 1, bl%ncorner(b)
                  cn = co%next(c)
                  if (max(c, cn) > th%nc) exit
                  a = 0.5_wp*abs((co%x(c) - bl%xc(b))*(co%y(cn) - bl%yc(b)) - &
                                 (co%x(cn) - bl%xc(b))*(co%y(c) - bl%yc(b)))
                  asum = asum + a
                  tsum = tsum + a*(th%bdtacc(b) + th%cdtacc(c) + th%cdtacc(cn))/3.0_wp
                  c = cn
               end do
               if (asum <= 0.0_wp) cycle
               ds = -kb*3.0_wp*alpha*tsum/asum
               bl%sxx(b) = bl%sxx(b) + ds
               bl%syy(b) = bl%syy(b) + ds
            end do
         end if
         if (th%nc > 0) th%cdtacc(1:th%nc) = 0.0_wp
         if (th%nb > 0) th%bdtacc(1:th%nb) = 0.0_wp
      end associate
   end subroutine thermal_apply_stress

   !> Put the points (node pn, position px py) inserted on one edge in
   !> order of their distance ps along it (perm: work).
   subroutine order_along_edge(pn, px, py, ps, perm)
      integer(ip), intent(inout) :: pn(:)
      real(wp), intent(inout) :: px(:), py(:), ps(:)
      integer(ip), intent(out) :: perm(:)
      call sort_order(ps, perm)
      pn = pn(perm)
      px = px(perm)
      py = py(perm)
      ps = ps(perm)
   end subroutine order_along_edge

end module thermal_conduction
