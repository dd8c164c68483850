!> The working triangulation of AUTO zoning (tri_t): vertices and triangles
!> with neighbour links, ear clipping of the corner polygon, point location
!> and insertion with Lawson flips (constrained Delaunay, the block boundary
!> being the constraint), and export to a mesh_t. docs/zones.md.
module zones_triangulation
   use core_arrays, only: push_back
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_arrays, only: grow_double
   use zones_mesh_base, only: mesh_t, nxt, prv, orient
   implicit none
   private
   public :: tri_t, loc_inside, loc_edge, loc_outside, loc_failed, tri_alloc, add_vertex, &
              new_triangle, set_tri, replace_nb, incircle, edge_len, ear_clip, flip, &
              should_flip, lawson, locate, insert_point, split_triangle, split_edge, edge_seg, &
              legalize, on_input_edge, across_sharp_corner, vertex_star, quality, circumcentre, &
              export

   !> Working triangulation. Triangle t has vertices v(1:3,t) counter-
   !> clockwise; n(i,t) is the triangle across the edge opposite v(i,t)
   !> (0: block boundary). Vertex kind: 0 interior, 1 input corner (seg =
   !> corner index), 2 on input edge seg (from corner seg to seg+1).
   type :: tri_t
      integer(ip) :: nv = 0, nt = 0, ncorner = 0
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: kind(:), seg(:), vtri(:)
      integer(ip), allocatable :: v(:, :), n(:, :)
      logical, allocatable :: sharp(:)          !< input corner below 60 degrees
      integer(ip) :: walk_seed = 0
      real(wp) :: scale = 1.0_wp                !< length scale for tolerances
   end type tri_t

   integer, parameter :: loc_inside = 1, loc_edge = 2, loc_outside = 3, loc_failed = 4

contains

   subroutine tri_alloc(tr, m)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: m
      allocate (tr%x(m), tr%y(m), tr%kind(m), tr%seg(m), tr%vtri(m))
      allocate (tr%v(3, 2*m), tr%n(3, 2*m))
   end subroutine tri_alloc

   subroutine add_vertex(tr, px, py, kind, seg, id)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: kind, seg
      integer(ip), intent(out) :: id
      real(wp), allocatable :: r(:)
      integer(ip), allocatable :: iv(:)
      integer(ip) :: m
      if (tr%nv >= size(tr%x)) then
         m = 2*size(tr%x)
         allocate (r(m)); r(1:tr%nv) = tr%x(1:tr%nv); call move_alloc(r, tr%x)
         allocate (r(m)); r(1:tr%nv) = tr%y(1:tr%nv); call move_alloc(r, tr%y)
         allocate (iv(m)); iv(1:tr%nv) = tr%kind(1:tr%nv); call move_alloc(iv, tr%kind)
         allocate (iv(m)); iv(1:tr%nv) = tr%seg(1:tr%nv); call move_alloc(iv, tr%seg)
         allocate (iv(m)); iv(1:tr%nv) = tr%vtri(1:tr%nv); call move_alloc(iv, tr%vtri)
      end if
      tr%nv = tr%nv + 1
      id = tr%nv
      tr%x(id) = px
      tr%y(id) = py
      tr%kind(id) = kind
      tr%seg(id) = seg
      tr%vtri(id) = 0
   end subroutine add_vertex

   subroutine new_triangle(tr, t)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(out) :: t
      integer(ip), allocatable :: a(:, :)
      integer(ip) :: m
      if (tr%nt >= size(tr%v, 2)) then
         m = 2*size(tr%v, 2)
         allocate (a(3, m)); a(:, 1:tr%nt) = tr%v(:, 1:tr%nt); call move_alloc(a, tr%v)
         allocate (a(3, m)); a(:, 1:tr%nt) = tr%n(:, 1:tr%nt); call move_alloc(a, tr%n)
      end if
      tr%nt = tr%nt + 1
      t = tr%nt
   end subroutine new_triangle

   subroutine set_tri(tr, t, a, b, c, na, nb, nc)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, a, b, c, na, nb, nc
      tr%v(:, t) = [a, b, c]
      tr%n(:, t) = [na, nb, nc]
      tr%vtri(a) = t
      tr%vtri(b) = t
      tr%vtri(c) = t
   end subroutine set_tri

   !> In triangle w (if any) the neighbour `old` becomes `new`.
   subroutine replace_nb(tr, w, old, new)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: w, old, new
      integer :: k
      if (w == 0) return
      do k = 1, 3
         if (tr%n(k, w) == old) then
            tr%n(k, w) = new
            return
         end if
      end do
   end subroutine replace_nb

   !> > 0 when d is inside the circumcircle of counter-clockwise a b c.
   pure real(wp) function incircle(ax, ay, bx, by, cx, cy, dx, dy)
      real(wp), intent(in) :: ax, ay, bx, by, cx, cy, dx, dy
      real(wp) :: adx, ady, bdx, bdy, cdx, cdy
      adx = ax - dx; ady = ay - dy
      bdx = bx - dx; bdy = by - dy
      cdx = cx - dx; cdy = cy - dy
      incircle = (adx*adx + ady*ady)*(bdx*cdy - cdx*bdy) &
                 - (bdx*bdx + bdy*bdy)*(adx*cdy - cdx*ady) &
                 + (cdx*cdx + cdy*cdy)*(adx*bdy - bdx*ady)
   end function incircle

   real(wp) function edge_len(tr, t, i)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b
      a = tr%v(nxt(i), t)
      b = tr%v(prv(i), t)
      edge_len = hypot(tr%x(b) - tr%x(a), tr%y(b) - tr%y(a))
   end function edge_len

   !> Ear clipping of the input corner polygon (vertices 1..ncorner, clockwise).
   subroutine ear_clip(tr, error)
      type(tri_t), intent(inout) :: tr
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: n, left, v, p, q, k, w, guard, t, a, b, i, j
      integer(ip), allocatable :: nx(:), pv(:), adj_start(:), adj(:), cnt(:)
      logical, allocatable :: convex(:), gone(:)
      logical :: ear
      real(wp) :: eps
      n = tr%ncorner
      allocate (nx(n), pv(n), convex(n), gone(n))
      ! counter-clockwise ring = reverse of the clockwise input
      do k = 1, n
         nx(k) = merge(n, k - 1, k == 1)
         pv(k) = merge(1_ip, k + 1, k == n)
      end do
      gone = .false.
      eps = 1.0e-12_wp*tr%scale**2
      do k = 1, n
         convex(k) = orient(tr%x(pv(k)), tr%y(pv(k)), tr%x(k), tr%y(k), tr%x(nx(k)), &
                            tr%y(nx(k))) > eps
      end do
      left = n
      v = 1
      guard = 0
      do while (left > 3)
         guard = guard + 1
         if (guard > 4*n*n + 100) then
            call set_error(error, 'the block boundary could not be triangulated')
            return
         end if
         p = pv(v); q = nx(v)
         ear = convex(v)
         if (ear) then
            w = nx(q)
            do while (w /= p)
               if (.not. convex(w)) then
                  if (in_closed_triangle(w)) then
                     ear = .false.
                     exit
                  end if
               end if
               w = nx(w)
            end do
         end if
         if (ear) then
            call new_triangle(tr, t)
            tr%v(:, t) = [p, v, q]
            nx(p) = q
            pv(q) = p
            gone(v) = .true.
            left = left - 1
            convex(p) = orient(tr%x(pv(p)), tr%y(pv(p)), tr%x(p), tr%y(p), tr%x(nx(p)), &
                               tr%y(nx(p))) > eps
            convex(q) = orient(tr%x(pv(q)), tr%y(pv(q)), tr%x(q), tr%y(q), tr%x(nx(q)), &
                               tr%y(nx(q))) > eps
            v = p
            guard = 0
         else
            v = q
         end if
      end do
      v = 1
      do while (gone(v))
         v = v + 1
      end do
      call new_triangle(tr, t)
      tr%v(:, t) = [pv(v), v, nx(v)]
      if (orient(tr%x(pv(v)), tr%y(pv(v)), tr%x(v), tr%y(v), tr%x(nx(v)), tr%y(nx(v))) <= 0) &
         then
         call set_error(error, 'the block boundary could not be triangulated')
         return
      end if
      ! neighbours through the triangles of each vertex
      allocate (cnt(n + 1), adj_start(n + 1), adj(3*tr%nt))
      cnt = 0
      do t = 1, tr%nt
         do i = 1, 3
            cnt(tr%v(i, t)) = cnt(tr%v(i, t)) + 1
         end do
      end do
      adj_start(1) = 1
      do k = 1, n
         adj_start(k + 1) = adj_start(k) + cnt(k)
      end do
      cnt = 0
      do t = 1, tr%nt
         do i = 1, 3
            k = tr%v(i, t)
            adj(adj_start(k) + cnt(k)) = t
            cnt(k) = cnt(k) + 1
            tr%vtri(k) = t
         end do
      end do
      tr%n(:, 1:tr%nt) = 0
      do t = 1, tr%nt
         do i = 1, 3
            a = tr%v(nxt(i), t)
            b = tr%v(prv(i), t)
            do k = adj_start(a), adj_start(a + 1) - 1
               w = adj(k)
               if (w == t) cycle
               do j = 1, 3
                  if (tr%v(j, w) == b .and. tr%v(nxt(j), w) == a) tr%n(i, t) = w
               end do
            end do
         end do
      end do
   contains
      logical function in_closed_triangle(w_)
         integer(ip), intent(in) :: w_
         real(wp) :: o1, o2, o3
         o1 = orient(tr%x(p), tr%y(p), tr%x(v), tr%y(v), tr%x(w_), tr%y(w_))
         o2 = orient(tr%x(v), tr%y(v), tr%x(q), tr%y(q), tr%x(w_), tr%y(w_))
         o3 = orient(tr%x(q), tr%y(q), tr%x(p), tr%y(p), tr%x(w_), tr%y(w_))
         in_closed_triangle = o1 >= -eps .and. o2 >= -eps .and. o3 >= -eps
      end function in_closed_triangle
   end subroutine ear_clip

   !> Flip the edge opposite v(i,t); afterwards t = (a, b, d), u = (a, d, c)
   !> where a = old v(i,t), so a stays vertex 1 of both.
   subroutine flip(tr, t, i)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b, c, d, u, j, nca, nab, nbd, ndc
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      u = tr%n(i, t)
      nca = tr%n(nxt(i), t)
      nab = tr%n(prv(i), t)
      do j = 1, 3
         if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
      end do
      d = tr%v(j, u)
      ! u = (d, c, b): opposite c is edge b-d, opposite b is edge d-c
      nbd = tr%n(nxt(j), u)
      ndc = tr%n(prv(j), u)
      call set_tri(tr, t, a, b, d, nbd, u, nab)
      call set_tri(tr, u, a, d, c, ndc, nca, t)
      call replace_nb(tr, nbd, u, t)
      call replace_nb(tr, nca, t, u)
   end subroutine flip

   !> True when the edge opposite v(i,t) may be flipped to improve Delaunay-ness.
   logical function should_flip(tr, t, i)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b, c, d, u, j
      real(wp) :: s2
      should_flip = .false.
      u = tr%n(i, t)
      if (u == 0) return
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      do j = 1, 3
         if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
      end do
      d = tr%v(j, u)
      s2 = max((tr%x(a) - tr%x(d))**2 + (tr%y(a) - tr%y(d))**2, &
               (tr%x(b) - tr%x(d))**2 + (tr%y(b) - tr%y(d))**2, &
               (tr%x(c) - tr%x(d))**2 + (tr%y(c) - tr%y(d))**2)
      if (incircle(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(c), tr%y(c), tr%x(d), tr%y(d)) &
          <= 1.0e-10_wp*s2*s2) return
      ! the quadrilateral a b d c must be strictly convex
      if (orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(d), tr%y(d)) <= 0.0_wp) return
      if (orient(tr%x(a), tr%y(a), tr%x(d), tr%y(d), tr%x(c), tr%y(c)) <= 0.0_wp) return
      should_flip = .true.
   end function should_flip

   !> Flip non-Delaunay edges of the triangles on the stack until none is left.
   subroutine lawson(tr, stack, ns)
      type(tri_t), intent(inout) :: tr
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: ns
      integer(ip) :: t, i, u, nflip
      nflip = 0
      do while (ns > 0)
         t = stack(ns)
         ns = ns - 1
         do i = 1, 3
            if (should_flip(tr, t, i)) then
               u = tr%n(i, t)
               call flip(tr, t, i)
               nflip = nflip + 1
               call push_back(stack, ns, t)
               call push_back(stack, ns, u)
               exit
            end if
         end do
         if (nflip > 50*(tr%nt + 100)) exit     ! round-off guard
      end do
      ns = 0
   end subroutine lawson

   !> Find the triangle containing (px, py) by walking from `start`.
   subroutine locate(tr, px, py, start, t, i, status)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: start
      integer(ip), intent(out) :: t, i, status
      integer(ip) :: steps, k, kk, best
      real(wp) :: o, eps, ob, l2
      t = start
      if (t < 1 .or. t > tr%nt) t = 1
      do steps = 1, 4*tr%nt + 100
         best = 0
         ob = 0.0_wp
         tr%walk_seed = modulo(tr%walk_seed + 1, 3_ip)
         do kk = 0, 2
            k = 1 + modulo(tr%walk_seed + kk, 3_ip)
            associate (a => tr%v(nxt(k), t), b => tr%v(prv(k), t))
               o = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), px, py)
               l2 = (tr%x(b) - tr%x(a))**2 + (tr%y(b) - tr%y(a))**2
            end associate
            eps = 1.0e-11_wp*l2
            if (o < -eps) then
               best = k
               exit
            else if (abs(o) <= eps) then
               ob = real(k, wp)
            end if
         end do
         if (best == 0) then
            if (ob > 0.0_wp) then
               i = int(ob, ip)
               status = loc_edge
            else
               i = 0
               status = loc_inside
            end if
            return
         end if
         if (tr%n(best, t) == 0) then
            i = best
            status = loc_outside
            return
         end if
         t = tr%n(best, t)
      end do
      ! the walk did not converge (round-off): search every triangle
      do t = 1, tr%nt
         kk = 0
         do k = 1, 3
            associate (a => tr%v(nxt(k), t), b => tr%v(prv(k), t))
               o = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), px, py)
               l2 = (tr%x(b) - tr%x(a))**2 + (tr%y(b) - tr%y(a))**2
            end associate
            if (o < -1.0e-11_wp*l2) kk = -1
         end do
         if (kk == 0) then
            i = 0
            status = loc_inside
            return
         end if
      end do
      status = loc_failed
      t = 0
      i = 0
   end subroutine locate

   !> Insert a vertex (kind, seg) at (px, py); status from `locate`. Points
   !> outside the block or on top of an existing vertex are not inserted.
   subroutine insert_point(tr, px, py, kind, seg, start, status)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: kind, seg, start
      integer(ip), intent(out) :: status
      integer(ip) :: t, i, k
      real(wp) :: d
      call locate(tr, px, py, start, t, i, status)
      if (status == loc_outside .or. status == loc_failed) return
      do k = 1, 3
         d = hypot(tr%x(tr%v(k, t)) - px, tr%y(tr%v(k, t)) - py)
         if (d <= 1.0e-9_wp*tr%scale) then
            status = loc_failed
            return
         end if
      end do
      if (status == loc_inside) then
         call split_triangle(tr, t, px, py, kind, seg)
      else
         call split_edge(tr, t, i, px, py, kind, seg)
      end if
   end subroutine insert_point

   subroutine split_triangle(tr, t, px, py, kind, seg)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, kind, seg
      real(wp), intent(in) :: px, py
      integer(ip) :: p, a, b, c, na, nb, nc, t1, t2, ns
      integer(ip), allocatable :: stack(:)
      call add_vertex(tr, px, py, kind, seg, p)
      a = tr%v(1, t); b = tr%v(2, t); c = tr%v(3, t)
      na = tr%n(1, t); nb = tr%n(2, t); nc = tr%n(3, t)
      call new_triangle(tr, t1)
      call new_triangle(tr, t2)
      call set_tri(tr, t1, p, c, a, nb, t2, t)
      call set_tri(tr, t2, p, a, b, nc, t, t1)
      call set_tri(tr, t, p, b, c, na, t1, t2)
      call replace_nb(tr, nb, t, t1)
      call replace_nb(tr, nc, t, t2)
      allocate (stack(16))
      ns = 0
      call push_back(stack, ns, t); call push_back(stack, ns, t1); call push_back(stack, ns, t2)
      call legalize(tr, p, stack, ns)
   end subroutine split_triangle

   !> Split the edge opposite v(i,t) at (px, py).
   subroutine split_edge(tr, t, i, px, py, kind, seg)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, i, kind, seg
      real(wp), intent(in) :: px, py
      integer(ip) :: p, a, b, c, d, u, j, nb, nc, nbd, ndc, t1, u1, ns, kd, sg
      integer(ip), allocatable :: stack(:)
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      nb = tr%n(nxt(i), t)     ! across c-a
      nc = tr%n(prv(i), t)     ! across a-b
      u = tr%n(i, t)
      kd = kind
      sg = seg
      if (u == 0 .and. kd == 0) then
         ! a point on the block boundary: it lies on the input edge of b-c
         kd = 2
         sg = edge_seg(tr, b, c)
      end if
      call add_vertex(tr, px, py, kd, sg, p)
      call new_triangle(tr, t1)
      if (u /= 0) then
         do j = 1, 3
            if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
         end do
         d = tr%v(j, u)
         nbd = tr%n(nxt(j), u)
         ndc = tr%n(prv(j), u)
         call new_triangle(tr, u1)
         call set_tri(tr, t, p, a, b, nc, u, t1)
         call set_tri(tr, t1, p, c, a, nb, t, u1)
         call set_tri(tr, u, p, b, d, nbd, u1, t)
         call set_tri(tr, u1, p, d, c, ndc, t1, u)
         call replace_nb(tr, nb, t, t1)
         call replace_nb(tr, ndc, u, u1)
      else
         call set_tri(tr, t, p, a, b, nc, 0_ip, t1)
         call set_tri(tr, t1, p, c, a, nb, t, 0_ip)
         call replace_nb(tr, nb, t, t1)
      end if
      allocate (stack(16))
      ns = 0
      call push_back(stack, ns, t); call push_back(stack, ns, t1)
      if (u /= 0) then
         call push_back(stack, ns, u); call push_back(stack, ns, u1)
      end if
      call legalize(tr, p, stack, ns)
   end subroutine split_edge

   !> Input edge a boundary piece b-c lies on.
   integer(ip) function edge_seg(tr, b, c) result(e)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: b, c
      integer(ip) :: n
      n = tr%ncorner
      if (tr%kind(b) == 2) then
         e = tr%seg(b)
      else if (tr%kind(c) == 2) then
         e = tr%seg(c)
      else
         ! two input corners, adjacent in the clockwise ring
         if (tr%seg(c) == merge(1_ip, tr%seg(b) + 1, tr%seg(b) == n)) then
            e = tr%seg(b)
         else
            e = tr%seg(c)
         end if
      end if
   end function edge_seg

   !> Lawson flips around a new vertex p (vertex 1 of the stacked triangles).
   subroutine legalize(tr, p, stack, ns)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: p
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: ns
      integer(ip) :: t, u, guard
      guard = 0
      do while (ns > 0)
         t = stack(ns)
         ns = ns - 1
         if (tr%v(1, t) /= p) cycle
         guard = guard + 1
         if (guard > 10000) exit
         if (should_flip(tr, t, 1_ip)) then
            u = tr%n(1, t)
            call flip(tr, t, 1_ip)
            call push_back(stack, ns, t)
            call push_back(stack, ns, u)
         end if
      end do
      ns = 0
   end subroutine legalize

   !> Is vertex v on input edge e (corners lie on their two edges)?
   logical function on_input_edge(tr, v, e)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v, e
      integer(ip) :: n
      n = tr%ncorner
      select case (tr%kind(v))
      case (1)
         on_input_edge = e == tr%seg(v) .or. e == merge(n, tr%seg(v) - 1, tr%seg(v) == 1)
      case (2)
         on_input_edge = e == tr%seg(v)
      case default
         on_input_edge = .false.
      end select
   end function on_input_edge

   !> Do u and w lie on the two edges of one sharp input corner?
   logical function across_sharp_corner(tr, u, w, equal_dist)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: u, w
      logical, intent(in) :: equal_dist
      integer(ip) :: k, e1, e2, n
      real(wp) :: du, dw
      across_sharp_corner = .false.
      if (tr%kind(u) == 0 .or. tr%kind(w) == 0) return
      n = tr%ncorner
      do k = 1, n
         if (.not. tr%sharp(k)) cycle
         e1 = merge(n, k - 1, k == 1)
         e2 = k
         if ((on_input_edge(tr, u, e1) .and. on_input_edge(tr, w, e2)) .or. &
             (on_input_edge(tr, u, e2) .and. on_input_edge(tr, w, e1))) then
            if (.not. equal_dist) then
               across_sharp_corner = .true.
               return
            end if
            ! concentric shells: only an edge between points at the same
            ! distance from the corner is left alone
            du = hypot(tr%x(u) - tr%x(k), tr%y(u) - tr%y(k))
            dw = hypot(tr%x(w) - tr%x(k), tr%y(w) - tr%y(k))
            if (abs(du - dw) <= 1.0e-3_wp*max(du, dw)) then
               across_sharp_corner = .true.
               return
            end if
         end if
      end do
   end function across_sharp_corner

   !> Triangles around v counter-clockwise and the ring of neighbours (the
   !> vertex after v in each triangle); `closed` false for boundary vertices.
   subroutine vertex_star(tr, v, star, ring, ns, closed)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v
      integer(ip), allocatable, intent(out) :: star(:), ring(:)
      integer(ip), intent(out) :: ns
      logical, intent(out) :: closed
      integer(ip) :: t, k, t0, guard
      allocate (star(32), ring(32))
      ns = 0
      closed = .false.
      t0 = tr%vtri(v)
      if (t0 == 0) return
      ! rotate clockwise to the first triangle (or all the way round)
      t = t0
      do guard = 1, 1000
         k = vpos(t)
         if (tr%n(nxt(k), t) == 0) exit     ! edge v - v(prv k) ... see below
         t = tr%n(nxt(k), t)
         if (t == t0) then
            closed = .true.
            exit
         end if
      end do
      ! t: the clockwise-most triangle; walk counter-clockwise
      t0 = t
      do guard = 1, 1000
         k = vpos(t)
         if (ns >= size(ring)) call grow_double(ring)
         call push_back(star, ns, t)
         ring(ns) = tr%v(nxt(k), t)
         if (tr%n(prv(k), t) == 0) exit
         t = tr%n(prv(k), t)
         if (t == t0) exit
      end do
   contains
      integer(ip) function vpos(tt)
         integer(ip), intent(in) :: tt
         do vpos = 1, 3
            if (tr%v(vpos, tt) == v) return
         end do
      end function vpos
   end subroutine vertex_star

   !> sin of the smallest angle of triangle t, longest and shortest edge, and
   !> the vertex opposite the shortest edge.
   subroutine quality(tr, t, q, lmax, lmin, imin)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t
      real(wp), intent(out) :: q, lmax, lmin
      integer(ip), intent(out) :: imin
      real(wp) :: l(3), a2
      integer(ip) :: i
      do i = 1, 3
         l(i) = edge_len(tr, t, i)
      end do
      associate (a => tr%v(1, t), b => tr%v(2, t), c => tr%v(3, t))
         a2 = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(c), tr%y(c))
      end associate
      imin = minloc(l, 1)
      lmax = maxval(l)
      lmin = minval(l)
      ! the smallest angle is opposite the shortest edge, between the other two
      q = a2/max((l(nxt(imin))*l(prv(imin))), tiny(1.0_wp))
   end subroutine quality

   subroutine circumcentre(tr, t, cx, cy)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t
      real(wp), intent(out) :: cx, cy
      real(wp) :: bx, by, qx, qy, d
      associate (a => tr%v(1, t), b => tr%v(2, t), c => tr%v(3, t))
         bx = tr%x(b) - tr%x(a); by = tr%y(b) - tr%y(a)
         qx = tr%x(c) - tr%x(a); qy = tr%y(c) - tr%y(a)
         d = 2.0_wp*(bx*qy - by*qx)
         cx = tr%x(a) + (qy*(bx*bx + by*by) - by*(qx*qx + qy*qy))/d
         cy = tr%y(a) + (bx*(qx*qx + qy*qy) - qx*(bx*bx + by*by))/d
      end associate
   end subroutine circumcentre

   !> Renumber: the boundary ring clockwise from input corner 1, then the
   !> interior points.
   subroutine export(tr, mesh)
      type(tri_t), intent(in) :: tr
      type(mesh_t), intent(out) :: mesh
      integer(ip), allocatable :: cw(:), newid(:)
      integer(ip) :: t, i, a, b, v, k, nb
      allocate (cw(tr%nv), newid(tr%nv))
      cw = 0
      do t = 1, tr%nt
         do i = 1, 3
            if (tr%n(i, t) /= 0) cycle
            a = tr%v(nxt(i), t); b = tr%v(prv(i), t)
            ! a -> b is counter-clockwise along the boundary
            cw(b) = a
         end do
      end do
      newid = 0
      nb = 0
      v = 1
      do
         nb = nb + 1
         newid(v) = nb
         v = cw(v)
         if (v == 1 .or. v == 0 .or. nb > tr%nv) exit
      end do
      mesh%nb = nb
      mesh%np = tr%nv
      allocate (mesh%x(tr%nv), mesh%y(tr%nv), mesh%orig(nb))
      k = nb
      do v = 1, tr%nv
         if (newid(v) == 0) then
            k = k + 1
            newid(v) = k
         end if
         mesh%x(newid(v)) = tr%x(v)
         mesh%y(newid(v)) = tr%y(v)
         if (newid(v) <= nb) mesh%orig(newid(v)) = merge(tr%seg(v), 0_ip, tr%kind(v) == 1)
      end do
      mesh%nt = tr%nt
      allocate (mesh%tri(3, tr%nt))
      do t = 1, tr%nt
         mesh%tri(:, t) = newid(tr%v(:, t))
      end do
   end subroutine export

end module zones_triangulation
