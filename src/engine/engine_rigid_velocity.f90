!> BOUNDARY XVEL / YVEL on the corners of rigid and simply-deformable blocks
!> (UDEC manual (ICG1.5, 1989), Section 4.5, BOUNDARY "Velocity (Displacement)
!> Boundary"; Section 6 keeps one boundary record per corner with KBDX / KBDY
!> = 4 for a velocity, whatever its block). A prescribed velocity component
!> at a corner r of a block moving as a rigid body (centroid velocity V,
!> angular velocity w) is the linear constraint
!>    XVEL v:  Vx - w (ry - yc) = v,     YVEL v:  Vy + w (rx - xc) = v.
!> After the block's free velocity update (stage block motion) the stage
!> "block velocities" projects (V, w) onto the constraints in the metric of
!> the block's inertia diag(m, m, I) (the smallest reaction that enforces
!> them: Gauss's principle of least constraint), moves the block by the
!> difference over the step, and reports as unbalanced force only the part
!> of the block's force the constraints do not hold. Constraints that
!> depend on others (three collinear rollers) are dropped, inconsistent ones
!> met in the least-squares sense. A FIXed block stays fixed. The strain
!> modes of an SDEF block are not constrained (its rigid modes are).
!>
!> Only a model with such a corner runs the stage (engine_stages); its list
!> of constrained blocks is built once per CYCLE.
module engine_rigid_velocity
   use core_kinds, only: wp, ip, i8
   use core_motion, only: stage_args_t
   use model_geometry, only: geometry_t
   use model_boundary, only: boundary_t, boundary_history_value, bc_velocity, bh_constant
   use engine_rigid, only: motion_work_t
   implicit none
   private
   public :: rigid_velocity_t, rigid_velocity_present, rigid_velocity_build, rigid_velocity_step, &
             rigid_velocity_free_force, rigid_velocity_reactions

   !> The constrained blocks of one CYCLE: block k's boundary points are
   !> pts(first(k) : first(k) + count(k) - 1).
   type :: rigid_velocity_t
      integer(ip) :: nblk = 0
      integer(ip), allocatable :: blk(:), first(:), cnt(:), pts(:)
   end type rigid_velocity_t

contains

   !> Boundary point i holds a velocity on a corner of a live block that moves
   !> as a rigid body (not zoned).
   logical function constrained_point(bnd, geo, i)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      integer(ip) :: c, b
      constrained_point = .false.
      if (bnd%ix(i) /= bc_velocity .and. bnd%iy(i) /= bc_velocity) return
      c = bnd%corner(i)
      if (c < 1 .or. c > geo%corners%n) return
      if (.not. geo%corners%live(c)) return
      if (geo%corners%gp(c) /= 0) return
      b = geo%corners%block(c)
      if (.not. geo%blocks%live(b)) return
      if (geo%blocks%fdef(b)) return
      constrained_point = .true.
   end function constrained_point

   !> The model has a velocity on a corner of a rigid or SDEF block.
   logical function rigid_velocity_present(bnd, geo)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip) :: i
      rigid_velocity_present = .false.
      do i = 1, bnd%n
         if (constrained_point(bnd, geo, i)) then
            rigid_velocity_present = .true.
            return
         end if
      end do
   end function rigid_velocity_present

   !> The constrained blocks and their points, grouped by block.
   subroutine rigid_velocity_build(bnd, geo, rv)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(rigid_velocity_t), intent(out) :: rv
      integer(ip), allocatable :: count_of(:), slot(:), idx(:)
      integer(ip) :: i, b, k, n
      allocate (count_of(geo%blocks%n))
      count_of = 0
      n = 0
      do i = 1, bnd%n
         if (.not. constrained_point(bnd, geo, i)) cycle
         b = geo%corners%block(bnd%corner(i))
         count_of(b) = count_of(b) + 1
         n = n + 1
      end do
      rv%nblk = count(count_of > 0)
      allocate (rv%blk(rv%nblk), rv%first(rv%nblk), rv%cnt(rv%nblk), rv%pts(n), &
                slot(geo%blocks%n), idx(rv%nblk))
      slot = 0
      k = 0
      n = 1
      do b = 1, geo%blocks%n
         if (count_of(b) == 0) cycle
         k = k + 1
         rv%blk(k) = b
         rv%first(k) = n
         rv%cnt(k) = 0
         slot(b) = k
         n = n + count_of(b)
      end do
      do i = 1, bnd%n
         if (.not. constrained_point(bnd, geo, i)) cycle
         k = slot(geo%corners%block(bnd%corner(i)))
         rv%pts(rv%first(k) + rv%cnt(k)) = i
         rv%cnt(k) = rv%cnt(k) + 1
      end do
   end subroutine rigid_velocity_build

   !> Project the constrained blocks' velocities (after rigid_motion), move
   !> them by the correction over dt (`sa%res%travel` grows by it), and recompute the
   !> largest unbalanced force of the rigid blocks (`sa%res%unbal`, `sa%res%at`) with the
   !> constrained directions' reactions left out. Velocities at step sa%k of sa%ncycles
   !> at problem time sa%time follow the points' histories as in boundary_step.
   !> The adaptive damping's sums of the step (`sa%res%dke`, `sa%res%edamp`, summed by
   !> rigid_motion from the free update) are corrected to the projected
   !> velocities: the free update of a held block is driven by its reaction,
   !> and counted as kinetic energy it made DAMP AUTO raise the damping to its
   !> limit (alpha dt = 1) in every model with such a block.
   subroutine rigid_velocity_step(rv, bnd, geo, work, sa)
      type(rigid_velocity_t), intent(in) :: rv
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(motion_work_t), intent(inout) :: work
      type(stage_args_t), intent(inout) :: sa
      integer(ip) :: j, b, ne, kk, nb
      real(wp) :: e(3, 3), s(3), sq(3), z(3), zf(3), f(3), fr, d(3)
      integer(ip), allocatable :: held(:)
      nb = geo%blocks%n
      allocate (held(nb))
      held = 0
      associate (bl => geo%blocks, co => geo%corners)
         do j = 1, rv%nblk
            b = rv%blk(j)
            if (.not. bl%live(b) .or. bl%fixed(b)) cycle
            held(b) = j
            call constraint_rows(rv, bnd, geo, j, b, work%m_in(b), work%i_in(b), e, s, sq, ne, &
                                 sa%time, sa%k, sa%ncycles)
            if (ne == 0) cycle
            z = sq*[bl%vx(b), bl%vy(b), bl%vr(b)]
            zf = z
            do kk = 1, ne
               zf = zf - (dot_product(e(:, kk), z) - s(kk))*e(:, kk)
            end do
            d = zf/sq - [bl%vx(b), bl%vy(b), bl%vr(b)]
            if (all(d == 0.0_wp)) cycle
            call energy_sums(b, -1.0_wp)
            call move_block(b, d)
            call energy_sums(b, 1.0_wp)
         end do
         ! the largest unbalanced force of the free rigid blocks, the held
         ! directions of the constrained ones left out
         sa%res%unbal = 0.0_wp
         sa%res%at = 0
         do b = 1, nb
            if (.not. bl%live(b) .or. bl%fixed(b) .or. bl%fdef(b)) cycle
            f = [work%b(4, b) + bl%mass(b)*sa%ms%grav(1) + bl%lx(b), &
                 work%b(5, b) + bl%mass(b)*sa%ms%grav(2) + bl%ly(b), work%b(6, b)]
            if (held(b) > 0) f = rigid_velocity_free_force(rv, bnd, geo, held(b), b, work%m_in(b), &
                                                           work%i_in(b), f)
            fr = sqrt(f(1)*f(1) + f(2)*f(2))
            if (.not. (fr <= sa%res%unbal)) then
               sa%res%unbal = fr
               sa%res%at = b
            end if
         end do
      end associate

   contains

      !> Add (sign 1) or take out (sign -1) block bb's share of the step's
      !> kinetic-energy change and damping work, as rigid_motion sums them,
      !> from its velocity at the start of the step (work%b(1:3, bb)) and now.
      subroutine energy_sums(bb, sign)
         integer(ip), intent(in) :: bb
         real(wp), intent(in) :: sign
         real(wp) :: v0(3), v1(3), mm(3)
         v0 = work%b(1:3, bb)
         v1 = [geo%blocks%vx(bb), geo%blocks%vy(bb), geo%blocks%vr(bb)]
         mm = [work%m_in(bb), work%m_in(bb), work%i_in(bb)]
         sa%res%dke = sa%res%dke + sign*abs(0.5_wp*sum(mm*(v1*v1 - v0*v0)))
         sa%res%edamp = sa%res%edamp + sign*sa%ms%alpha*sa%ms%dt*0.25_wp*sum(mm*(v0 + v1)**2)
      end subroutine energy_sums

      !> Change block bb's velocity by dv and move it by dv dt (rotation about
      !> its present centroid), saving its corners for an undo first.
      subroutine move_block(bb, dv)
         integer(ip), intent(in) :: bb
         real(wp), intent(in) :: dv(3)
         integer(ip) :: cc, m, s
         real(wp) :: dx, dy, dth, cs, sn, xo, yo, xn, yn, rad2
         associate (bl => geo%blocks, co => geo%corners)
            if (.not. work%moved(bb)) then
               cc = bl%first_corner(bb)
               do m = 1, bl%ncorner(bb)
                  s = work%cslot(bb) + m
                  work%c(1, s) = co%x(cc); work%c(2, s) = co%y(cc)
                  work%c(3, s) = co%rx(cc); work%c(4, s) = co%ry(cc)
                  work%c(5, s) = co%ux(cc); work%c(6, s) = co%uy(cc)
                  cc = co%next(cc)
               end do
               work%p(1, bb) = bl%xc(bb); work%p(2, bb) = bl%yc(bb)
               work%p(3, bb) = bl%ux(bb); work%p(4, bb) = bl%uy(bb)
               work%p(5, bb) = bl%rot(bb)
               work%moved(bb) = .true.
            end if
            bl%vx(bb) = bl%vx(bb) + dv(1)
            bl%vy(bb) = bl%vy(bb) + dv(2)
            bl%vr(bb) = bl%vr(bb) + dv(3)
            dx = dv(1)*sa%ms%dt
            dy = dv(2)*sa%ms%dt
            dth = dv(3)*sa%ms%dt
            cs = cos(dth)
            sn = sin(dth)
            xo = bl%xc(bb)
            yo = bl%yc(bb)
            bl%xc(bb) = xo + dx
            bl%yc(bb) = yo + dy
            bl%ux(bb) = bl%ux(bb) + dx
            bl%uy(bb) = bl%uy(bb) + dy
            bl%rot(bb) = bl%rot(bb) + dth
            rad2 = 0.0_wp
            cc = bl%first_corner(bb)
            do m = 1, bl%ncorner(bb)
               rad2 = max(rad2, (co%x(cc) - xo)**2 + (co%y(cc) - yo)**2)
               xn = bl%xc(bb) + cs*(co%x(cc) - xo) - sn*(co%y(cc) - yo)
               yn = bl%yc(bb) + sn*(co%x(cc) - xo) + cs*(co%y(cc) - yo)
               co%ux(cc) = co%ux(cc) + (xn - co%x(cc))
               co%uy(cc) = co%uy(cc) + (yn - co%y(cc))
               co%x(cc) = xn
               co%y(cc) = yn
               xn = bl%xc(bb) + cs*(co%rx(cc) - xo) - sn*(co%ry(cc) - yo)
               yn = bl%yc(bb) + sn*(co%rx(cc) - xo) + cs*(co%ry(cc) - yo)
               co%rx(cc) = xn
               co%ry(cc) = yn
               cc = co%next(cc)
            end do
            sa%res%travel = max(sa%res%travel, sqrt(dx*dx + dy*dy) + abs(dth)*sqrt(rad2))
         end associate
      end subroutine move_block
   end subroutine rigid_velocity_step

   !> The constraint rows (e, s, ne) of constrained block jj of rv (block bb)
   !> in the metric of its inertia diag(m, m, inertia) (sq: its square root;
   !> z = M^(1/2) q, rows a M^(-1/2)), Gram-Schmidt orthonormal: one for each
   !> independent held direction of its points. The values s are the
   !> prescribed velocities at step k of ncycles at problem time `time`
   !> (following the points' histories as in boundary_step), or 0 without
   !> them. ne = 0 for a block without inertia.
   subroutine constraint_rows(rv, bnd, geo, jj, bb, m, inertia, e, s, sq, ne, time, k, ncycles)
      type(rigid_velocity_t), intent(in) :: rv
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: jj, bb
      real(wp), intent(in) :: m, inertia
      real(wp), intent(out) :: e(3, 3), s(3), sq(3)
      integer(ip), intent(out) :: ne
      real(wp), intent(in), optional :: time
      integer(i8), intent(in), optional :: k, ncycles
      integer(ip) :: pp, ii, cc
      real(wp) :: rx, ry, v
      ne = 0
      sq = [sqrt(m), sqrt(m), sqrt(inertia)]
      if (any(sq <= 0.0_wp)) return
      do pp = rv%first(jj), rv%first(jj) + rv%cnt(jj) - 1
         ii = rv%pts(pp)
         cc = bnd%corner(ii)
         rx = geo%corners%x(cc) - geo%blocks%xc(bb)
         ry = geo%corners%y(cc) - geo%blocks%yc(bb)
         if (bnd%ix(ii) == bc_velocity) then
            v = 0.0_wp
            if (present(time)) v = bnd%xmul(ii)*bnd%vx(ii)*history(bnd%hx(ii), bnd%freqx(ii), &
                                                                   bnd%tloadx(ii))
            call add_row([1.0_wp, 0.0_wp, -ry]/sq, v)
         end if
         if (bnd%iy(ii) == bc_velocity) then
            v = 0.0_wp
            if (present(time)) v = bnd%ymul(ii)*bnd%vy(ii)*history(bnd%hy(ii), bnd%freqy(ii), &
                                                                   bnd%tloady(ii))
            call add_row([0.0_wp, 1.0_wp, rx]/sq, v)
         end if
      end do

   contains

      !> h(t) of a point's history in one direction (1 for CONSTANT).
      real(wp) function history(hcode, freq, tload) result(hv)
         integer, intent(in) :: hcode
         real(wp), intent(in) :: freq, tload
         hv = 1.0_wp
         if (hcode /= bh_constant) hv = boundary_history_value(bnd, hcode, freq, tload, time, &
                                                               k, ncycles)
      end function history

      !> Gram-Schmidt: one more constraint row (scaled) with its value.
      subroutine add_row(row, val)
         real(wp), intent(in) :: row(3), val
         call orthonormal_append(row, val, e, s, ne)
      end subroutine add_row
   end subroutine constraint_rows

   !> The force (fx, fy, moment) of block bb, constrained block jj of rv,
   !> without its components along the velocity constraints in the metric of
   !> its inertia diag(m, m, inertia): what the constraints do not hold, and
   !> so what is out of balance (the cycle and PRINT MAX).
   function rigid_velocity_free_force(rv, bnd, geo, jj, bb, m, inertia, force) result(fo)
      type(rigid_velocity_t), intent(in) :: rv
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: jj, bb
      real(wp), intent(in) :: m, inertia, force(3)
      real(wp) :: fo(3), g(3), e(3, 3), s(3), sq(3)
      integer(ip) :: ne, q
      fo = force
      call constraint_rows(rv, bnd, geo, jj, bb, m, inertia, e, s, sq, ne)
      if (ne == 0) return
      g = force/sq
      do q = 1, ne
         g = g - dot_product(e(:, q), g)*e(:, q)
      end do
      fo = g*sq
   end function rigid_velocity_free_force

   !> The reactions at the held points of constrained block jj of rv (block
   !> bb) under its force (fx, fy, moment): the part the constraints hold
   !> (force less rigid_velocity_free_force) shared among the points' held
   !> directions as the smallest set of corner forces (least squares) with
   !> that resultant and moment: unique for up to three independent held
   !> directions; a rigid block held in more is statically indeterminate and
   !> has no stiffness to share it otherwise. rx(p), ry(p): the reaction of
   !> point rv%pts(rv%first(jj) + p - 1), 0 in a free direction. The force
   !> the block puts on its supports, as PRINT BOUNDARY FORCES gives a held
   !> gridpoint's (zone and contact forces plus its weight): the reactions
   !> of a block at rest add up to its weight and loads.
   subroutine rigid_velocity_reactions(rv, bnd, geo, jj, bb, m, inertia, force, rx, ry)
      type(rigid_velocity_t), intent(in) :: rv
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: jj, bb
      real(wp), intent(in) :: m, inertia, force(3)
      real(wp), intent(out) :: rx(:), ry(:)
      real(wp) :: fc(3), y(3), cx, cy
      real(wp), allocatable :: a(:, :), q(:, :), lam(:)
      integer(ip) :: pp, ii, n, j, k, nq, np
      np = rv%cnt(jj)
      rx(1:np) = 0.0_wp
      ry(1:np) = 0.0_wp
      fc = force - rigid_velocity_free_force(rv, bnd, geo, jj, bb, m, inertia, force)
      ! one column per held direction: its unit force's (fx, fy, moment)
      allocate (a(3, 2*np), q(2*np, 3), lam(2*np))
      a = 0.0_wp
      do pp = 1, np
         ii = rv%pts(rv%first(jj) + pp - 1)
         cx = geo%corners%x(bnd%corner(ii)) - geo%blocks%xc(bb)
         cy = geo%corners%y(bnd%corner(ii)) - geo%blocks%yc(bb)
         if (bnd%ix(ii) == bc_velocity) a(:, 2*pp - 1) = [1.0_wp, 0.0_wp, -cy]
         if (bnd%iy(ii) == bc_velocity) a(:, 2*pp) = [0.0_wp, 1.0_wp, cx]
      end do
      n = 2*np
      ! the smallest lam with a lam = fc: lam in the span of a's rows,
      ! orthonormalised (Gram-Schmidt); a dependent row's equation follows
      ! from the others (fc lies in a's range)
      nq = 0
      do j = 1, 3
         call orthonormal_append(a(j, 1:n), fc(j), q, y, nq)
      end do
      lam = 0.0_wp
      do k = 1, nq
         lam = lam + y(k)*q(:, k)
      end do
      do pp = 1, np
         rx(pp) = lam(2*pp - 1)
         ry(pp) = lam(2*pp)
      end do
   end subroutine rigid_velocity_reactions

   !> Gram-Schmidt: append row (with its value val) to the orthonormal rows
   !> basis(:, 1:nb) (values vals), unless it depends on them (within 1e-9
   !> of its length) or the basis is full.
   pure subroutine orthonormal_append(row, val, basis, vals, nb)
      real(wp), intent(in) :: row(:), val
      real(wp), intent(inout) :: basis(:, :), vals(:)
      integer(ip), intent(inout) :: nb
      real(wp) :: r(size(row)), sv, w, nrm
      integer(ip) :: q
      r = row
      sv = val
      do q = 1, nb
         w = dot_product(row, basis(:, q))
         r = r - w*basis(:, q)
         sv = sv - w*vals(q)
      end do
      nrm = sqrt(dot_product(r, r))
      if (nrm <= 1.0e-9_wp*sqrt(dot_product(row, row))) return   ! dependent
      if (nb >= size(basis, 2)) return
      nb = nb + 1
      basis(:, nb) = r/nrm
      vals(nb) = sv/nrm
   end subroutine orthonormal_append

end module engine_rigid_velocity
