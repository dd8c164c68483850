!> Mechanics of rock reinforcement (UDEC manual (ICG1.5, 1989), Section 3.10),
!> one cycle stage ("reinforcement") that a model without REINFORCE or CABLE
!> never runs.
!>
!> Local reinforcement (Section 3.10.1, Figs. 3-15 to 3-17): two springs at
!> the joint. The active length (2 RLENGTH along the bolt axis a) turns with
!> the relative displacement d of the two sides: its direction is
!> e = (2 RLENGTH a + d) / |..|. The axial spring (RASTIFF, bound RUAXIAL, the
!> same in tension and compression, Fig. 3-13) takes the increment of d along
!> a plus the part of its increment along e - a reduced by the crushing
!> factor r_f = |u_axial| / |d| (Eq. 42, at most 1; u_axial the sum of the
!> increments of d along e). The shear spring (RSSTIFF) stays perpendicular
!> to the original axis (p = (-a_y, a_x)); its bound is Eq. 41,
!> RUSHEAR (1 + sgn(du_s) cos theta_0) / 2 with cos theta_0 = a . t (t the
!> joint tangent, du_s the shear increment along t): full when shear
!> stretches a bolt lying along the joint, half for a perpendicular bolt.
!> Both springs follow the continuously-yielding law of Eqs. 43-44 as we
!> read it: loading (increment in the direction of the force)
!> dF = K du (1 - |F| / F_b)^exp (exp = RAEXP / RSEXP; exp 0 is elastic-
!> perfectly plastic); a reversal unloads with RRFAC K (RRFAC 0 taken as 1).
!> The force -(F_a e + F_s p) acts on side 2 at its material point and the
!> opposite on side 1 (rigid block: force and moment; FDEF block: shared by
!> the two gridpoints of the edge).
!>
!> Cables (Section 3.10.2, Figs. 3-18, 3-19): element axial force
!> N += E A / L0 dL (tension +; E = 9KG / (3K + G) of material mats; N within
!> [-YCOMP, YIELD], a zero bound meaning none), starting at the pretension.
!> A hosted node moves with its host point (zone weights, Eq. 48, or the
!> rigid block's motion) across the cable and slips along the local cable
!> direction t (the chord of its neighbours) by the axial out-of-balance
!> force; the grout spring fg -= JKS glen ds, |fg| <= JCOH glen (units of
!> Section 4.5, force per unit cable length) resists the slip ds. The host
!> receives the nodal force less its axial part plus the grout reaction,
!> distributed by the same weights (Eq. 52). A free node (in no block) has
!> two degrees of freedom. Gravity acts on the cable's mass (rho A glen).
!>
!> Time step: a cable node's inertial mass is raised, when needed, so that
!> the node is stable at half its critical step (m = k dt^2, k the grout
!> spring plus 2 E A / L of each element) -- the nodes never limit the step
!> (the manual's KBDSF density scaling). The springs' stiffness bounds the
!> step of the blocks and gridpoints they act on (dt_block, dt_gp), which the
!> engine combines with its own bounds.
module reinforce_mechanics
   use core_forces, only: add_rigid_force, add_shared_force
   use core_kinds, only: wp, ip
   use core_motion, only: motion_result_t, stage_args_t
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_properties, only: prop_bulk, prop_density, prop_jcoh, prop_jks, prop_raexp, &
                                 prop_rastiff, prop_rlength, prop_rrfac, prop_rsexp, &
                                 prop_rsstiff, prop_ruaxial, prop_rushear, prop_shear, &
                                 prop_ycomp, prop_yield
   use model_reinforcement, only: reinforcement_t, reinf_joint_normal
   implicit none
   private
   public :: reinf_work_t, reinforce_prepare, reinforce_fit_masses, reinforce_step
   public :: reinforce_save, reinforce_restore, cy_increment

   !> Workspace of the reinforcement stage for one CYCLE command.
   type :: reinf_work_t
      logical :: active = .false.
      !> REINFORCE: per element RASTIFF, RSSTIFF, RLENGTH, RUAXIAL, RUSHEAR, RRFAC, RSEXP, RAEXP
      real(wp), allocatable :: rp(:, :)
      !> cables: per element E A / L0, YIELD, YCOMP; per node JKS glen, JCOH glen,
      !> inertial mass, stiffness, direction (tx, ty), slip increment of the step
      real(wp), allocatable :: kax(:), yld(:), ycp(:)
      real(wp), allocatable :: kg(:), fgmax(:), m_in(:), knode(:), tx(:), ty(:), ds(:)
      real(wp) :: dt_block = huge(1.0_wp), dt_gp = huge(1.0_wp)
      !> state before the current step (reinforce_save)
      real(wp), allocatable :: saved(:)
      logical :: have_saved = .false.
   end type reinf_work_t

contains

   include 'core_damping.inc'

   !> Properties, masses and the stiffness bounds before a CYCLE. `mblock` and
   !> `mgp`: inertial masses of the blocks and gridpoints (mgp may be empty).
   !> Errors name the material and what it lacks.
   subroutine reinforce_prepare(rf, geo, mats, mblock, mgp, work, error)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      real(wp), intent(in) :: mblock(:), mgp(:)
      type(reinf_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: i, m, a, b, nn, ne, k
      real(wp) :: kmax, gsh, bulk, e, rho
      real(wp), allocatable :: kb(:), kgp(:)
      character(len=:), allocatable :: missing
      work%active = rf%reinf%n > 0 .or. rf%nodes%n > 0
      work%have_saved = .false.
      allocate (kb(geo%blocks%n), kgp(geo%gridpoints%n))
      kb = 0.0_wp
      kgp = 0.0_wp
      ! local reinforcement
      if (allocated(work%rp)) deallocate (work%rp)
      allocate (work%rp(8, max(1_ip, rf%reinf%n)))
      associate (r => rf%reinf)
         do i = 1, r%n
            m = r%material(i)
            work%rp(:, i) = [mats%get(int(m), prop_rastiff), mats%get(int(m), prop_rsstiff), &
                             mats%get(int(m), prop_rlength), mats%get(int(m), prop_ruaxial), &
                             mats%get(int(m), prop_rushear), mats%get(int(m), prop_rrfac), &
                             mats%get(int(m), prop_rsexp), mats%get(int(m), prop_raexp)]
            if (any(work%rp(1:5, i) <= 0.0_wp)) then
               missing = ''
               if (work%rp(1, i) <= 0.0_wp) missing = missing//' RASTIFF=..'
               if (work%rp(2, i) <= 0.0_wp) missing = missing//' RSSTIFF=..'
               if (work%rp(3, i) <= 0.0_wp) missing = missing//' RLENGTH=..'
               if (work%rp(4, i) <= 0.0_wp) missing = missing//' RUAXIAL=..'
               if (work%rp(5, i) <= 0.0_wp) missing = missing//' RUSHEAR=..'
               call set_error(error, 'CYCLE: reinforcement element '//itoa(i)//' (material '// &
                              itoa(m)//') needs RASTIFF, RSSTIFF, RLENGTH, RUAXIAL and '// &
                              'RUSHEAR > 0: give PROPERTY MAT='//itoa(m)//missing)
               return
            end if
            if (work%rp(6, i) <= 0.0_wp) work%rp(6, i) = 1.0_wp
            kmax = max(work%rp(1, i), work%rp(2, i))*max(1.0_wp, work%rp(6, i))
            call add_k(r%block1(i), r%g1a(i), r%g1b(i), kmax)
            call add_k(r%block2(i), r%g2a(i), r%g2b(i), kmax)
         end do
      end associate
      ! cables
      nn = rf%nodes%n
      ne = rf%elements%n
      if (allocated(work%kax)) deallocate (work%kax, work%yld, work%ycp, work%kg, work%fgmax, &
                                           work%m_in, work%knode, work%tx, work%ty, work%ds)
      allocate (work%kax(max(1_ip, ne)), work%yld(max(1_ip, ne)), work%ycp(max(1_ip, ne)), &
                work%kg(max(1_ip, nn)), work%fgmax(max(1_ip, nn)), work%m_in(max(1_ip, nn)), &
                work%knode(max(1_ip, nn)), work%tx(max(1_ip, nn)), work%ty(max(1_ip, nn)), &
                work%ds(max(1_ip, nn)))
      work%ds = 0.0_wp
      associate (nd => rf%nodes, el => rf%elements)
         nd%mass(1:nn) = 0.0_wp
         work%knode(1:nn) = 0.0_wp
         do i = 1, ne
            m = el%mats(i)
            gsh = mats%get(int(m), prop_shear)
            bulk = mats%get(int(m), prop_bulk)
            rho = mats%get(int(m), prop_density)
            if (gsh <= 0.0_wp .or. bulk <= 0.0_wp) then
               call set_error(error, 'CYCLE: cable '//itoa(el%cable(i))//' (steel material '// &
                              itoa(m)//') needs its elastic moduli: give PROPERTY MAT='// &
                              itoa(m)//' K=.. G=.. (and DENSITY, YIELD, YCOMP)')
               return
            end if
            e = 9.0_wp*bulk*gsh/(3.0_wp*bulk + gsh)
            work%kax(i) = e*el%area(i)/el%length0(i)
            work%yld(i) = mats%get(int(m), prop_yield)
            work%ycp(i) = mats%get(int(m), prop_ycomp)
            a = el%n1(i)
            b = el%n2(i)
            nd%mass(a) = nd%mass(a) + 0.5_wp*rho*el%area(i)*el%length0(i)
            nd%mass(b) = nd%mass(b) + 0.5_wp*rho*el%area(i)*el%length0(i)
            work%knode(a) = work%knode(a) + 2.0_wp*work%kax(i)
            work%knode(b) = work%knode(b) + 2.0_wp*work%kax(i)
         end do
         do k = 1, nn
            work%kg(k) = 0.0_wp
            work%fgmax(k) = 0.0_wp
            if (nd%block(k) == 0) cycle
            m = nd%matg(k)
            work%kg(k) = mats%get(int(m), prop_jks)*nd%glen(k)
            work%fgmax(k) = mats%get(int(m), prop_jcoh)*nd%glen(k)
            if (work%kg(k) <= 0.0_wp .or. work%fgmax(k) <= 0.0_wp) then
               call set_error(error, 'CYCLE: cable '//itoa(nd%cable(k))//' (grout material '// &
                              itoa(m)//') needs the grout''s stiffness and strength per unit '// &
                              'length: give PROPERTY MAT='//itoa(m)//' JKS=.. JCOH=..')
               return
            end if
            work%knode(k) = work%knode(k) + work%kg(k)
            if (nd%zone(k) > 0) then
               associate (zn => geo%zones)
                  call add_k(nd%block(k), zn%g1(nd%zone(k)), zn%g2(nd%zone(k)), work%kg(k))
                  call add_k(nd%block(k), zn%g3(nd%zone(k)), 0_ip, work%kg(k))
               end associate
            else
               call add_k(nd%block(k), 0_ip, 0_ip, work%kg(k))
            end if
         end do
         work%m_in(1:nn) = nd%mass(1:nn)
      end associate
      call node_directions(rf, work)
      ! stiffness bounds of what the springs act on
      work%dt_block = huge(1.0_wp)
      work%dt_gp = huge(1.0_wp)
      do b = 1, geo%blocks%n
         if (kb(b) <= 0.0_wp .or. b > size(mblock)) cycle
         if (.not. geo%blocks%live(b) .or. geo%blocks%fixed(b) .or. mblock(b) <= 0.0_wp) cycle
         work%dt_block = min(work%dt_block, 2.0_wp*sqrt(mblock(b)/kb(b)))
      end do
      do k = 1, min(geo%gridpoints%n, size(mgp, kind=ip))
         if (kgp(k) <= 0.0_wp .or. mgp(k) <= 0.0_wp) cycle
         work%dt_gp = min(work%dt_gp, 2.0_wp*sqrt(mgp(k)/kgp(k)))
      end do
   contains
      !> Stiffness kk on block bb (twice, for its rotation) or on gridpoints ga, gb.
      subroutine add_k(bb, ga, gb, kk0)
         integer(ip), intent(in) :: bb, ga, gb
         real(wp), intent(in) :: kk0
         if (ga > 0) then
            kgp(ga) = kgp(ga) + kk0
            if (gb > 0) kgp(gb) = kgp(gb) + kk0
         else if (bb > 0) then
            kb(bb) = kb(bb) + 2.0_wp*kk0
         end if
      end subroutine add_k
   end subroutine reinforce_prepare

   !> The cable nodes' inertial masses for step dt (module header).
   subroutine reinforce_fit_masses(rf, work, dt)
      type(reinforcement_t), intent(in) :: rf
      type(reinf_work_t), intent(inout) :: work
      real(wp), intent(in) :: dt
      integer(ip) :: k
      do k = 1, rf%nodes%n
         work%m_in(k) = max(rf%nodes%mass(k), work%knode(k)*dt*dt)
      end do
   end subroutine reinforce_fit_masses

   !> The local cable direction at each node: the chord of its neighbours
   !> (an end node: its element).
   subroutine node_directions(rf, work)
      type(reinforcement_t), intent(in) :: rf
      type(reinf_work_t), intent(inout) :: work
      integer(ip) :: i, a, b
      real(wp) :: dx, dy, l
      associate (nd => rf%nodes, el => rf%elements)
         work%tx(1:nd%n) = 0.0_wp; work%ty(1:nd%n) = 0.0_wp
         do i = 1, el%n
            a = el%n1(i); b = el%n2(i)
            dx = nd%x(b) - nd%x(a); dy = nd%y(b) - nd%y(a)
            work%tx(a) = work%tx(a) + dx; work%ty(a) = work%ty(a) + dy
            work%tx(b) = work%tx(b) + dx; work%ty(b) = work%ty(b) + dy
         end do
         do i = 1, nd%n
            l = sqrt(work%tx(i)**2 + work%ty(i)**2)
            if (l > 0.0_wp) then
               work%tx(i) = work%tx(i)/l
               work%ty(i) = work%ty(i)/l
            end if
         end do
      end associate
   end subroutine node_directions

   !> One increment of a continuously-yielding spring (module header):
   !> force f, stiffness k, displacement increment du, bound fb, exponent ex,
   !> reversal factor rr.
   pure subroutine cy_increment(f, k, du, fb, ex, rr)
      real(wp), intent(inout) :: f
      real(wp), intent(in) :: k, du, fb, ex, rr
      real(wp) :: r
      if (du == 0.0_wp) return
      if (f*du >= 0.0_wp) then
         r = max(0.0_wp, 1.0_wp - abs(f)/fb)
         if (ex == 1.0_wp) then
            f = f + k*du*r
         else if (ex > 0.0_wp) then
            f = f + k*du*r**ex
         else
            f = f + k*du
         end if
      else
         f = f + rr*k*du
      end if
      f = max(-fb, min(fb, f))
   end subroutine cy_increment

   !> One step of the stage: cable node motion (with dt > 0), cable element
   !> and grout forces, local reinforcement forces, all into the force sums
   !> of blocks and gridpoints. With dt = 0 only the present forces are
   !> assembled (the first step's force sums). Damping: mass-proportional
   !> alpha, DAMP LOCAL's -aloc |F| sign(v) per direction. Returns in `sa%res`
   !> the largest unbalanced force of a cable node and that node (NaN caught);
   !> its energies and travel stay zero (not summed for DAMP AUTO).
   subroutine reinforce_step(rf, geo, work, sa)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(inout) :: geo
      type(reinf_work_t), intent(inout) :: work
      type(stage_args_t), intent(inout) :: sa
      sa%res = motion_result_t()
      if (rf%nodes%n > 0) then
         if (sa%ms%dt > 0.0_wp) call reinforce_fit_masses(rf, work, sa%ms%dt)
         if (sa%ms%dt > 0.0_wp) call cable_motion()
         call cable_forces(rf, geo, work, sa%ms%grav, sa%ms%dt)
      end if
      if (rf%reinf%n > 0) call reinf_forces(rf, geo, work, sa%ms%dt)
   contains
      !> Cable node motion: the slip of a node along its cable, or a free node's x, y
      !> (Eq. 28 with DAMP LOCAL), its host point following the block or zone.
      subroutine cable_motion()
         integer(ip) :: k, b, z
         real(wp) :: fx, fy, fa, hvx, hvy, m, f
         associate (nd => rf%nodes, gp => geo%gridpoints)
            do k = 1, nd%n
               m = work%m_in(k)
               fx = nd%fx(k) + nd%mass(k)*sa%ms%grav(1)
               fy = nd%fy(k) + nd%mass(k)*sa%ms%grav(2)
               b = nd%block(k)
               z = nd%zone(k)
               if (b > 0) then
                  if (.not. geo%blocks%live(b)) cycle
                  fa = fx*work%tx(k) + fy*work%ty(k) + nd%fg(k)
                  if (m > 0.0_wp) nd%vs(k) = damped_velocity(nd%vs(k), fa, m, sa%ms%dt, &
                                                             sa%ms%aloc, sa%ms%con1, sa%ms%con2)
                  f = abs(fa)
                  call host_velocity(rf, geo, k, hvx, hvy)
                  work%ds(k) = nd%vs(k)*sa%ms%dt
                  nd%slip(k) = nd%slip(k) + work%ds(k)
                  nd%x(k) = nd%x(k) + (hvx + nd%vs(k)*work%tx(k))*sa%ms%dt
                  nd%y(k) = nd%y(k) + (hvy + nd%vs(k)*work%ty(k))*sa%ms%dt
                  if (z > 0) then
                     associate (zn => geo%zones)
                        nd%hx(k) = nd%w1(k)*gp%x(zn%g1(z)) + nd%w2(k)*gp%x(zn%g2(z)) + &
                                   nd%w3(k)*gp%x(zn%g3(z))
                        nd%hy(k) = nd%w1(k)*gp%y(zn%g1(z)) + nd%w2(k)*gp%y(zn%g2(z)) + &
                                   nd%w3(k)*gp%y(zn%g3(z))
                     end associate
                  else
                     nd%hx(k) = nd%hx(k) + hvx*sa%ms%dt
                     nd%hy(k) = nd%hy(k) + hvy*sa%ms%dt
                  end if
               else
                  if (m > 0.0_wp) then
                     nd%vx(k) = damped_velocity(nd%vx(k), fx, m, sa%ms%dt, sa%ms%aloc, &
                                                sa%ms%con1, sa%ms%con2)
                     nd%vy(k) = damped_velocity(nd%vy(k), fy, m, sa%ms%dt, sa%ms%aloc, &
                                                sa%ms%con1, sa%ms%con2)
                  end if
                  f = hypot(fx, fy)
                  nd%x(k) = nd%x(k) + nd%vx(k)*sa%ms%dt
                  nd%y(k) = nd%y(k) + nd%vy(k)*sa%ms%dt
                  nd%hx(k) = nd%x(k)
                  nd%hy(k) = nd%y(k)
               end if
               if (.not. (f <= sa%res%unbal)) then        ! also catches NaN
                  sa%res%unbal = f
                  sa%res%at = k
               end if
            end do
         end associate
      end subroutine cable_motion
   end subroutine reinforce_step

   !> Host velocity of node k.
   pure subroutine host_velocity(rf, geo, k, vx, vy)
      type(reinforcement_t), intent(in) :: rf
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: k
      real(wp), intent(out) :: vx, vy
      integer(ip) :: b, z
      associate (nd => rf%nodes, gp => geo%gridpoints, bl => geo%blocks)
         b = nd%block(k)
         z = nd%zone(k)
         if (z > 0) then
            associate (zn => geo%zones)
               vx = nd%w1(k)*gp%vx(zn%g1(z)) + nd%w2(k)*gp%vx(zn%g2(z)) + nd%w3(k)*gp%vx(zn%g3(z))
               vy = nd%w1(k)*gp%vy(zn%g1(z)) + nd%w2(k)*gp%vy(zn%g2(z)) + nd%w3(k)*gp%vy(zn%g3(z))
            end associate
         else
            vx = bl%vx(b) - bl%vr(b)*(nd%hy(k) - bl%yc(b))
            vy = bl%vy(b) + bl%vr(b)*(nd%hx(k) - bl%xc(b))
         end if
      end associate
   end subroutine host_velocity

   subroutine cable_forces(rf, geo, work, grav, dt)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(inout) :: geo
      type(reinf_work_t), intent(inout) :: work
      real(wp), intent(in) :: grav(2), dt
      integer(ip) :: i, a, b, k, z
      real(wp) :: dx, dy, l, n, fx, fy, fa, hx, hy
      associate (nd => rf%nodes, el => rf%elements, gp => geo%gridpoints, bl => geo%blocks)
         nd%fx(1:nd%n) = 0.0_wp
         nd%fy(1:nd%n) = 0.0_wp
         do i = 1, el%n
            a = el%n1(i)
            b = el%n2(i)
            dx = nd%x(b) - nd%x(a)
            dy = nd%y(b) - nd%y(a)
            l = sqrt(dx*dx + dy*dy)
            n = el%axial(i)
            if (dt > 0.0_wp) then
               n = n + work%kax(i)*(l - el%length(i))
               if (work%yld(i) > 0.0_wp) n = min(n, work%yld(i))
               if (work%ycp(i) > 0.0_wp) n = max(n, -work%ycp(i))
               el%axial(i) = n
               el%length(i) = l
            end if
            if (l > 0.0_wp) then
               fx = n*dx/l
               fy = n*dy/l
               nd%fx(a) = nd%fx(a) + fx; nd%fy(a) = nd%fy(a) + fy
               nd%fx(b) = nd%fx(b) - fx; nd%fy(b) = nd%fy(b) - fy
            end if
         end do
         call node_directions(rf, work)
         do k = 1, nd%n
            b = nd%block(k)
            if (b == 0) cycle
            if (.not. bl%live(b)) cycle
            if (dt > 0.0_wp) then
               nd%fg(k) = nd%fg(k) - work%kg(k)*work%ds(k)
               nd%fg(k) = max(-work%fgmax(k), min(work%fgmax(k), nd%fg(k)))
            end if
            ! the host takes the nodal force but its axial part, and the grout reaction
            fx = nd%fx(k) + nd%mass(k)*grav(1)
            fy = nd%fy(k) + nd%mass(k)*grav(2)
            fa = fx*work%tx(k) + fy*work%ty(k)
            hx = fx - (fa + nd%fg(k))*work%tx(k)
            hy = fy - (fa + nd%fg(k))*work%ty(k)
            z = nd%zone(k)
            if (z > 0) then
               associate (zn => geo%zones)
                  gp%fx(zn%g1(z)) = gp%fx(zn%g1(z)) + nd%w1(k)*hx
                  gp%fy(zn%g1(z)) = gp%fy(zn%g1(z)) + nd%w1(k)*hy
                  gp%fx(zn%g2(z)) = gp%fx(zn%g2(z)) + nd%w2(k)*hx
                  gp%fy(zn%g2(z)) = gp%fy(zn%g2(z)) + nd%w2(k)*hy
                  gp%fx(zn%g3(z)) = gp%fx(zn%g3(z)) + nd%w3(k)*hx
                  gp%fy(zn%g3(z)) = gp%fy(zn%g3(z)) + nd%w3(k)*hy
               end associate
            else
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, nd%hx(k) - bl%xc(b), &
                                    nd%hy(k) - bl%yc(b), hx, hy)
            end if
         end do
      end associate
   end subroutine cable_forces

   !> Local reinforcement kernel (module header).
   subroutine reinf_forces(rf, geo, work, dt)
      type(reinforcement_t), intent(inout) :: rf
      type(geometry_t), intent(inout) :: geo
      type(reinf_work_t), intent(in) :: work
      real(wp), intent(in) :: dt
      integer(ip) :: i, b1, b2
      real(wp) :: v1x, v1y, v2x, v2y, ddx, ddy, ex, ey, l, px, py, dua, dus, rfac, dn, cos0, &
                  fsb, fx, fy, nx, ny
      associate (r => rf%reinf, gp => geo%gridpoints, bl => geo%blocks)
         do i = 1, r%n
            b1 = r%block1(i)
            b2 = r%block2(i)
            if (.not. (bl%live(b1) .and. bl%live(b2))) cycle
            px = -r%ay(i)
            py = r%ax(i)
            if (dt > 0.0_wp) then
               call side(b1, r%g1a(i), r%g1b(i), r%w1(i), r%x1(i), r%y1(i), v1x, v1y)
               call side(b2, r%g2a(i), r%g2b(i), r%w2(i), r%x2(i), r%y2(i), v2x, v2y)
               ddx = (v2x - v1x)*dt
               ddy = (v2y - v1y)*dt
               r%dx(i) = r%dx(i) + ddx
               r%dy(i) = r%dy(i) + ddy
            end if
            ex = 2.0_wp*work%rp(3, i)*r%ax(i) + r%dx(i)
            ey = 2.0_wp*work%rp(3, i)*r%ay(i) + r%dy(i)
            l = sqrt(ex*ex + ey*ey)
            ex = ex/l
            ey = ey/l
            if (dt > 0.0_wp) then
               r%uaxial(i) = r%uaxial(i) + ddx*ex + ddy*ey
               dn = sqrt(r%dx(i)**2 + r%dy(i)**2)
               rfac = 1.0_wp
               if (dn > 0.0_wp) rfac = min(1.0_wp, abs(r%uaxial(i))/dn)
               dua = ddx*r%ax(i) + ddy*r%ay(i) + rfac*(ddx*(ex - r%ax(i)) + ddy*(ey - r%ay(i)))
               dus = ddx*px + ddy*py
               call cy_increment(r%fa(i), work%rp(1, i), dua, work%rp(4, i), work%rp(8, i), &
                                 work%rp(6, i))
               ! Eq. 41: the shear bound for the bolt's attitude and the shear direction
               cos0 = r%ax(i)*r%tx(i) + r%ay(i)*r%ty(i)
               fsb = work%rp(5, i)*0.5_wp*(1.0_wp + sign(1.0_wp, ddx*r%tx(i) + ddy*r%ty(i))*cos0)
               fsb = max(fsb, 1.0e-6_wp*work%rp(5, i))
               call cy_increment(r%fs(i), work%rp(2, i), dus, fsb, work%rp(7, i), work%rp(6, i))
            end if
            ! force on side 2, and its opposite on side 1
            fx = -(r%fa(i)*ex + r%fs(i)*px)
            fy = -(r%fa(i)*ey + r%fs(i)*py)
            call reinf_joint_normal(r, i, nx, ny)
            r%fjs(i) = -(fx*r%tx(i) + fy*r%ty(i))
            r%fjn(i) = -(fx*nx + fy*ny)
            call apply(b2, r%g2a(i), r%g2b(i), r%w2(i), r%x2(i), r%y2(i), fx, fy)
            call apply(b1, r%g1a(i), r%g1b(i), r%w1(i), r%x1(i), r%y1(i), -fx, -fy)
         end do
      end associate
   contains
      !> Velocity of a side's material point; the point moves with it.
      subroutine side(b, ga, gb, w, x, y, vx, vy)
         integer(ip), intent(in) :: b, ga, gb
         real(wp), intent(in) :: w
         real(wp), intent(inout) :: x, y
         real(wp), intent(out) :: vx, vy
         associate (gp => geo%gridpoints, bl => geo%blocks)
            if (ga > 0 .and. gb > 0) then
               vx = (1.0_wp - w)*gp%vx(ga) + w*gp%vx(gb)
               vy = (1.0_wp - w)*gp%vy(ga) + w*gp%vy(gb)
               x = (1.0_wp - w)*gp%x(ga) + w*gp%x(gb)
               y = (1.0_wp - w)*gp%y(ga) + w*gp%y(gb)
            else
               vx = bl%vx(b) - bl%vr(b)*(y - bl%yc(b))
               vy = bl%vy(b) + bl%vr(b)*(x - bl%xc(b))
               x = x + vx*dt
               y = y + vy*dt
            end if
         end associate
      end subroutine side
      subroutine apply(b, ga, gb, w, x, y, fx0, fy0)
         integer(ip), intent(in) :: b, ga, gb
         real(wp), intent(in) :: w, x, y, fx0, fy0
         associate (gp => geo%gridpoints, bl => geo%blocks)
            if (ga > 0 .and. gb > 0) then
               call add_shared_force(gp%fx, gp%fy, ga, gb, w, fx0, fy0)
            else
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, x - bl%xc(b), y - bl%yc(b), fx0, fy0)
            end if
         end associate
      end subroutine apply
   end subroutine reinf_forces

   !> Keep the state a step changes (before the step), so that a numerical
   !> failure can restore the last good state (as structure_save).
   subroutine reinforce_save(rf, work)
      type(reinforcement_t), intent(inout) :: rf
      type(reinf_work_t), intent(inout) :: work
      integer(ip) :: need
      need = 13*rf%reinf%n + 11*rf%nodes%n + 2*rf%elements%n
      if (allocated(work%saved)) then
         if (size(work%saved, kind=ip) < need) deallocate (work%saved)
      end if
      if (.not. allocated(work%saved)) allocate (work%saved(max(1_ip, need)))
      call pack_state(rf, work%saved, .true.)
      work%have_saved = .true.
   end subroutine reinforce_save

   !> Undo a step: the state as reinforce_save found it.
   subroutine reinforce_restore(rf, work)
      type(reinforcement_t), intent(inout) :: rf
      type(reinf_work_t), intent(inout) :: work
      if (.not. work%have_saved) return
      call pack_state(rf, work%saved, .false.)
   end subroutine reinforce_restore

   !> Copy the moving state to (save) or from the buffer.
   subroutine pack_state(rf, buf, save)
      type(reinforcement_t), intent(inout) :: rf
      real(wp), intent(inout) :: buf(:)
      logical, intent(in) :: save
      integer(ip) :: p
      p = 0
      associate (r => rf%reinf, nd => rf%nodes, el => rf%elements)
         call cp(r%x1, r%n); call cp(r%y1, r%n); call cp(r%x2, r%n); call cp(r%y2, r%n)
         call cp(r%dx, r%n); call cp(r%dy, r%n); call cp(r%uaxial, r%n); call cp(r%fa, r%n)
         call cp(r%fs, r%n); call cp(r%fjs, r%n); call cp(r%fjn, r%n)
         p = p + 2*r%n
         call cp(nd%x, nd%n); call cp(nd%y, nd%n); call cp(nd%hx, nd%n); call cp(nd%hy, nd%n)
         call cp(nd%vs, nd%n); call cp(nd%vx, nd%n); call cp(nd%vy, nd%n); call cp(nd%fg, nd%n)
         call cp(nd%slip, nd%n); call cp(nd%fx, nd%n); call cp(nd%fy, nd%n)
         call cp(el%length, el%n); call cp(el%axial, el%n)
      end associate
   contains
      subroutine cp(a, n)
         real(wp), allocatable, intent(inout) :: a(:)
         integer(ip), intent(in) :: n
         if (n == 0) return
         if (save) then
            buf(p + 1:p + n) = a(1:n)
         else
            a(1:n) = buf(p + 1:p + n)
         end if
         p = p + n
      end subroutine cp
   end subroutine pack_state

end module reinforce_mechanics
