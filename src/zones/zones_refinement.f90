!> Delaunay refinement (Ruppert) and smoothing of an AUTO triangulation:
!> the lattice of interior points, encroached boundary pieces halved, poor
!> or long triangles split at their circumcentre (sharp corners protected),
!> Laplacian smoothing that never lowers the smallest angle. docs/zones.md.
module zones_refinement
   use core_arrays, only: push_back
   use core_sort, only: sort_values
   use core_kinds, only: wp, ip
   use core_constants, only: pi
   use geometry_polygon, only: segment_distance
   use zones_mesh_base, only: mesh_target_angle, nxt, prv
   use zones_triangulation, only: tri_t, loc_inside, loc_edge, loc_outside, edge_len, &
                                  locate, insert_point, split_edge, across_sharp_corner, &
                                  vertex_star, quality, circumcentre
   implicit none
   private
   public :: insert_lattice, refine, split_point, encroached_near, push_star, smooth

contains

   !> Hexagonal lattice of spacing h, points at least h/2 inside the
   !> boundary, inserted row by row in snake order (short walks).
   subroutine insert_lattice(tr, x, y, h, count)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: x(:), y(:), h
      integer(ip), intent(out) :: count
      real(wp) :: xmin, xmax, ymin, ymax, dy, y0, x0, yr, xs(size(x) + 2), dmin, px, d, t
      integer(ip) :: nrow, ncol, r, n, i, j, nx, c, k, st, last, c0, c1, dc
      logical :: ok
      count = 0
      n = size(x)
      xmin = minval(x); xmax = maxval(x); ymin = minval(y); ymax = maxval(y)
      dy = h*sqrt(3.0_wp)/2.0_wp
      dmin = 0.5_wp*h
      if (ymax - ymin < 2.0_wp*dmin .or. xmax - xmin < 2.0_wp*dmin) return
      nrow = int((ymax - ymin)/dy) + 1
      y0 = ymin + 0.5_wp*((ymax - ymin) - real(nrow - 1, wp)*dy)
      ncol = int((xmax - xmin)/h) + 2
      x0 = xmin + 0.5_wp*((xmax - xmin) - real(ncol - 1, wp)*h) - 0.25_wp*h
      last = tr%vtri(1)
      do r = 0, nrow - 1
         yr = y0 + real(r, wp)*dy
         ! crossings of the row with the boundary
         nx = 0
         j = n
         do i = 1, n
            if ((y(i) > yr) .neqv. (y(j) > yr)) then
               nx = nx + 1
               xs(nx) = x(i) + (yr - y(i))*(x(j) - x(i))/(y(j) - y(i))
            end if
            j = i
         end do
         call sort_values(xs(1:nx))
         if (mod(r, 2_ip) == 0) then
            c0 = 0; c1 = ncol; dc = 1
         else
            c0 = ncol; c1 = 0; dc = -1
         end if
         do c = c0, c1, dc
            px = x0 + real(c, wp)*h + merge(0.5_wp*h, 0.0_wp, mod(r, 2_ip) == 1)
            ok = .false.
            do k = 1, nx - 1, 2
               if (px > xs(k) + dmin .and. px < xs(k + 1) - dmin) ok = .true.
            end do
            if (.not. ok) cycle
            ! distance to every edge near the row
            j = n
            do i = 1, n
               if (min(y(i), y(j)) < yr + dmin .and. max(y(i), y(j)) > yr - dmin) then
                  call segment_distance(px, yr, x(j), y(j), x(i), y(i), d, t)
                  if (d < dmin) then
                     ok = .false.
                     exit
                  end if
               end if
               j = i
            end do
            if (.not. ok) cycle
            call insert_point(tr, px, yr, 0, 0, last, st)
            if (st == loc_inside .or. st == loc_edge) then
               count = count + 1
               last = tr%vtri(tr%nv)
            end if
         end do
      end do
   end subroutine insert_lattice

   !> Ruppert refinement: split encroached boundary pieces, then insert the
   !> circumcentre of triangles with a small angle or an edge above edmax.
   subroutine refine(tr, edmax, maxv)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: edmax
      integer(ip), intent(in) :: maxv
      integer(ip) :: head, t, i, a, b, c, st, u, k, j, ntri0
      integer(ip), allocatable :: queue(:)
      integer(ip) :: nq
      real(wp) :: s_target, cx, cy, q, lmax, lmin
      logical :: done
      s_target = sin(mesh_target_angle*pi/180.0_wp)
      allocate (queue(max(16_ip, 2*tr%nt)))
      nq = 0
      do t = 1, tr%nt
         call push_back(queue, nq, t)
      end do
      head = 0
      do while (head < nq)
         if (tr%nv >= maxv) exit
         head = head + 1
         t = queue(head)
         if (head > 1000000 .and. head > nq/2) then
            queue(1:nq - head) = queue(head + 1:nq)
            nq = nq - head
            head = 0
         end if
         ntri0 = tr%nt
         done = .false.
         ! encroached boundary pieces (apex inside the diametral circle)
         do i = 1, 3
            if (tr%n(i, t) /= 0) cycle
            a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
            if ((tr%x(b) - tr%x(a))*(tr%x(c) - tr%x(a)) + (tr%y(b) - tr%y(a))*(tr%y(c) - &
                tr%y(a)) >= 0.0_wp) cycle
            if (across_sharp_corner(tr, a, b, .false.) .or. across_sharp_corner(tr, a, c, .false.)) cycle
            if (edge_len(tr, t, i) < 1.0e-6_wp*tr%scale) cycle
            call split_point(tr, b, c, cx, cy)
            call split_edge(tr, t, i, cx, cy, 0_ip, 0_ip)
            done = .true.
            exit
         end do
         if (.not. done) then
            call quality(tr, t, q, lmax, lmin, i)
            if (q < s_target .or. lmax > edmax*(1.0_wp + 1.0e-6_wp)) then
               ! i: vertex opposite the shortest edge
               if (lmax <= edmax*(1.0_wp + 1.0e-6_wp) .and. &
                   across_sharp_corner(tr, tr%v(nxt(i), t), tr%v(prv(i), t), .true.)) then
                  cycle
               end if
               if (lmin < 1.0e-6_wp*tr%scale) cycle
               call circumcentre(tr, t, cx, cy)
               call locate(tr, cx, cy, t, u, k, st)
               if (st == loc_outside) then
                  ! beyond a boundary piece: split that piece instead
                  if (edge_len(tr, u, k) >= 1.0e-6_wp*tr%scale) then
                     b = tr%v(nxt(k), u); c = tr%v(prv(k), u)
                     call split_point(tr, b, c, cx, cy)
                     call split_edge(tr, u, k, cx, cy, 0_ip, 0_ip)
                     done = .true.
                  end if
               else if (st == loc_inside .or. st == loc_edge) then
                  call encroached_near(tr, u, cx, cy, j, k)
                  if (j > 0) then
                     b = tr%v(nxt(k), j); c = tr%v(prv(k), j)
                     call split_point(tr, b, c, cx, cy)
                     call split_edge(tr, j, k, cx, cy, 0_ip, 0_ip)
                     done = .true.
                  else
                     call insert_point(tr, cx, cy, 0_ip, 0_ip, u, st)
                     done = st == loc_inside .or. st == loc_edge
                  end if
               end if
            end if
         end if
         if (done) then
            ! the changed triangles: the new ones and those around the new point
            do k = ntri0 + 1, tr%nt
               call push_back(queue, nq, k)
            end do
            call push_star(tr, tr%nv, queue, nq)
            call push_back(queue, nq, t)
         end if
      end do
   end subroutine refine

   !> Where to split boundary piece b-c: the midpoint, or, next to a corner
   !> sharper than 60 degrees, the point whose distance from the corner is
   !> the power of two (times the block extent) nearest half the piece
   !> (concentric shells: both edges of the corner get points at the same
   !> distances, so the zones in the corner are isosceles).
   subroutine split_point(tr, b, c, px, py)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: b, c
      real(wp), intent(out) :: px, py
      integer(ip) :: o, f
      real(wp) :: l, d
      px = 0.5_wp*(tr%x(b) + tr%x(c))
      py = 0.5_wp*(tr%y(b) + tr%y(c))
      o = 0
      if (tr%kind(b) == 1) then
         if (tr%sharp(tr%seg(b))) then
            o = b; f = c
         end if
      end if
      if (o == 0 .and. tr%kind(c) == 1) then
         if (tr%sharp(tr%seg(c))) then
            o = c; f = b
         end if
      end if
      if (o == 0) return
      l = hypot(tr%x(f) - tr%x(o), tr%y(f) - tr%y(o))
      d = tr%scale*2.0_wp**nint(log(0.5_wp*l/tr%scale)/log(2.0_wp))
      if (d <= 0.2_wp*l .or. d >= 0.8_wp*l) return
      px = tr%x(o) + (tr%x(f) - tr%x(o))*d/l
      py = tr%y(o) + (tr%y(f) - tr%y(o))*d/l
   end subroutine split_point

   !> Boundary piece of u or its neighbours whose diametral circle holds (cx, cy).
   subroutine encroached_near(tr, u, cx, cy, j, k)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: u
      real(wp), intent(in) :: cx, cy
      integer(ip), intent(out) :: j, k
      integer(ip) :: cand(4), m, i, b, c
      cand(1) = u
      cand(2:4) = tr%n(:, u)
      do m = 1, 4
         j = cand(m)
         if (j == 0) cycle
         do i = 1, 3
            if (tr%n(i, j) /= 0) cycle
            b = tr%v(nxt(i), j); c = tr%v(prv(i), j)
            if ((tr%x(b) - cx)*(tr%x(c) - cx) + (tr%y(b) - cy)*(tr%y(c) - cy) < 0.0_wp) then
               k = i
               return
            end if
         end do
      end do
      j = 0
      k = 0
   end subroutine encroached_near

   !> Push every triangle around vertex v.
   subroutine push_star(tr, v, queue, nq)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v
      integer(ip), allocatable, intent(inout) :: queue(:)
      integer(ip), intent(inout) :: nq
      integer(ip), allocatable :: star(:), ring(:)
      integer(ip) :: ns, k
      logical :: closed
      call vertex_star(tr, v, star, ring, ns, closed)
      do k = 1, ns
         call push_back(queue, nq, star(k))
      end do
   end subroutine push_star

   !> Laplacian smoothing of interior vertices; a move is kept only when the
   !> smallest angle around the vertex does not drop.
   subroutine smooth(tr, passes, edmax)
      type(tri_t), intent(inout) :: tr
      integer, intent(in) :: passes
      real(wp), intent(in) :: edmax
      integer(ip), allocatable :: star(:), ring(:)
      integer(ip) :: v, ns, k, pass
      logical :: closed
      real(wp) :: x0, y0, xn, yn, q0, q1
      do pass = 1, passes
         do v = 1, tr%nv
            if (tr%kind(v) /= 0) cycle
            call vertex_star(tr, v, star, ring, ns, closed)
            if (.not. closed .or. ns < 3) cycle
            x0 = tr%x(v); y0 = tr%y(v)
            xn = 0.0_wp; yn = 0.0_wp
            do k = 1, ns
               xn = xn + tr%x(ring(k)); yn = yn + tr%y(ring(k))
            end do
            xn = xn/ns; yn = yn/ns
            q0 = star_quality(star, ns)
            tr%x(v) = xn; tr%y(v) = yn
            q1 = star_quality(star, ns)
            if (.not. q1 > q0 .or. star_edge(ring, ns) > edmax) then
               tr%x(v) = x0; tr%y(v) = y0
            end if
         end do
      end do
   contains
      real(wp) function star_edge(rg, m) result(l)
         integer(ip), intent(in) :: rg(:), m
         integer(ip) :: kk
         l = 0.0_wp
         do kk = 1, m
            l = max(l, hypot(tr%x(rg(kk)) - tr%x(v), tr%y(rg(kk)) - tr%y(v)))
         end do
      end function star_edge
      real(wp) function star_quality(st, m) result(qq)
         integer(ip), intent(in) :: st(:), m
         integer(ip) :: kk, im
         real(wp) :: q, lmax, lmin
         qq = huge(1.0_wp)
         do kk = 1, m
            call quality(tr, st(kk), q, lmax, lmin, im)
            qq = min(qq, q)
         end do
      end function star_quality
   end subroutine smooth

end module zones_refinement
