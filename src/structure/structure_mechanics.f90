!> Mechanics of structural elements (manual Section 3.11, explicit
!> formulation, Fig. 3-21): lumped masses at the nodes move like gridpoints
!> (force sums -> accelerations -> velocities with the cycle's mass-
!> proportional damping -> positions), beam elements give the node forces
!> (structure_models) and interfaces tie the nodes to the block edges.
!>
!> Masses: each element gives rho A L0 / 2 to each of its nodes, and the
!> rotary inertia (rho A L0 / 2) L0^2 / 12 (A = thickness x 1).
!> Element material: DENSITY, BULK, SHEAR (E = 9KG / (3K + G)); interface
!> material (the same number, manual 4.5 STRUCTURE note): KN, KS [force /
!> displacement], CCOHESION, CTENSILE [force], CFRICTION.
!>
!> Interface (a spring pair, like a point contact of JCONS 1): the node's
!> relative velocity to the block at the contact point (the node projected on
!> the block edge, interpolated between the edge's gridpoints of an FDEF block
!> or from the rigid-block motion) gives the increments of un and us;
!>   fn = -KN un (compression positive); beyond the tensile strength
!>   (fn < -CTENSILE) the interface breaks: no tension and no cohesion after;
!>   fs -= KS dus, |fs| <= CCOHESION + CFRICTION max(fn, 0).
!> The force fn n + fs t acts on the node and its opposite on the block
!> (distributed to the edge's two gridpoints by the projection weights).
!>
!> Time step: Gershgorin's bound on the highest frequency of a node with the
!> mass-normalised row sums of the element stiffness (axial, bending, their
!> coupling) and the interface springs; dt_node = 2 / omega.
module structure_mechanics
   use core_forces, only: add_rigid_force, add_shared_force
   use core_kinds, only: wp, ip
   use core_motion, only: motion_result_t, stage_args_t
   use model_properties, only: prop_bulk, prop_ccohesion, prop_cfriction, prop_ctensile, &
                                 prop_density, prop_kn, prop_ks, prop_shear
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_structures, only: structure_t, sfix_x, sfix_y, sfix_r, iface_broken, iface_slip
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use structure_models, only: beam_props_t, beam_model_t, beam_model_create
   use reinforce_mechanics, only: reinf_work_t
   implicit none
   private
   public :: structure_work_t, structure_prepare, structure_timestep, structure_fit_masses
   public :: structure_motion, structure_force_pass, structure_young
   public :: structure_save, structure_restore

   type :: model_holder_t
      class(beam_model_t), allocatable :: model
   end type model_holder_t

   !> Workspace of the structure stage for one CYCLE command.
   type :: structure_work_t
      logical :: active = .false.
      integer :: ngroup = 0
      integer(ip), allocatable :: gstart(:), gidx(:)
      type(beam_props_t), allocatable :: gprops(:)
      type(model_holder_t), allocatable :: models(:)
      real(wp), allocatable :: m_in(:), i_in(:)       !< inertial mass and rotary inertia
      real(wp), allocatable :: omega2(:)              !< bound on the squared frequency per node
      real(wp), allocatable :: kn(:), ks(:), coh(:), fric(:), tens(:)   !< per interface
      !> Node state before the current step (structure_save): x, y, vx, vy,
      !> vr, ux, uy, rot per node; nsaved nodes.
      real(wp), allocatable :: saved(:, :)
      integer(ip) :: nsaved = 0
      !> the reinforcement stage's workspace (reinforce_mechanics), carried here
      type(reinf_work_t) :: rw
   end type structure_work_t

contains

   include 'core_damping.inc'

   !> Young's modulus from bulk and shear moduli.
   pure real(wp) function structure_young(k, g) result(e)
      real(wp), intent(in) :: k, g
      e = 0.0_wp
      if (3.0_wp*k + g > 0.0_wp) e = 9.0_wp*k*g/(3.0_wp*k + g)
   end function structure_young

   !> Groups, section properties, masses, interface springs and frequency
   !> bounds before a CYCLE. Errors name the material and what it lacks.
   subroutine structure_prepare(st, mats, work, error)
      type(structure_t), intent(inout) :: st
      type(material_table_t), intent(in) :: mats
      type(structure_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: e, j, a, b, i, nn
      integer :: g, ng
      integer(ip), allocatable :: gmat(:), gcount(:), fill(:), egroup(:)
      real(wp) :: rho, k, gsh, ea, ei, l, mh, mmin, jmin
      real(wp), allocatable :: wt(:), wr(:)
      character(len=:), allocatable :: missing
      work%active = st%elements%n > 0 .or. st%nodes%n > 0
      associate (nd => st%nodes, el => st%elements, it => st%interfaces)
         nn = nd%n
         ! groups by element material
         allocate (gmat(0), gcount(0), egroup(max(1_ip, el%n)))
         ng = 0
         do e = 1, el%n
            do g = 1, ng
               if (gmat(g) == el%material(e)) exit
            end do
            if (g > ng) then
               ng = ng + 1
               gmat = [gmat, el%material(e)]
               gcount = [gcount, 0_ip]
            end if
            egroup(e) = g
            gcount(g) = gcount(g) + 1
         end do
         work%ngroup = ng
         if (allocated(work%gstart)) deallocate (work%gstart, work%gidx, work%gprops, work%models)
         allocate (work%gstart(ng + 1), work%gidx(max(1_ip, el%n)), work%gprops(ng), work%models(ng))
         work%gstart(1) = 1
         do g = 1, ng
            work%gstart(g + 1) = work%gstart(g) + gcount(g)
            rho = mats%get(int(gmat(g)), prop_density)
            k = mats%get(int(gmat(g)), prop_bulk)
            gsh = mats%get(int(gmat(g)), prop_shear)
            missing = ''
            if (rho <= 0.0_wp) missing = missing//' DENSITY=..'
            if (k <= 0.0_wp) missing = missing//' K=..'
            if (gsh <= 0.0_wp) missing = missing//' G=..'
            if (len(missing) > 0) then
               call set_error(error, 'CYCLE: structural elements of material '//itoa(gmat(g))// &
                              ' need density, bulk and shear modulus: give PROPERTY MAT='// &
                              itoa(gmat(g))//missing)
               return
            end if
            work%gprops(g)%material = gmat(g)
            work%gprops(g)%density = rho
            work%gprops(g)%young = structure_young(k, gsh)
            call beam_model_create('ELASTIC', work%models(g)%model, error)
            if (allocated(error)) return
         end do
         allocate (fill(ng))
         fill = work%gstart(1:ng)
         do e = 1, el%n
            g = egroup(e)
            work%gidx(fill(g)) = e
            fill(g) = fill(g) + 1
         end do
         ! interface springs
         if (allocated(work%kn)) deallocate (work%kn, work%ks, work%coh, work%fric, work%tens)
         allocate (work%kn(max(1_ip, it%n)), work%ks(max(1_ip, it%n)), work%coh(max(1_ip, it%n)), &
                   work%fric(max(1_ip, it%n)), work%tens(max(1_ip, it%n)))
         do i = 1, it%n
            work%kn(i) = mats%get(int(it%material(i)), prop_kn)
            work%ks(i) = mats%get(int(it%material(i)), prop_ks)
            work%coh(i) = mats%get(int(it%material(i)), prop_ccohesion)
            work%fric(i) = mats%get(int(it%material(i)), prop_cfriction)
            work%tens(i) = mats%get(int(it%material(i)), prop_ctensile)
            if (work%kn(i) <= 0.0_wp) then
               call set_error(error, 'CYCLE: the interface of structure node '// &
                              itoa(it%node(i))//' (material '//itoa(it%material(i))// &
                              ') has no normal stiffness: give PROPERTY MAT='// &
                              itoa(it%material(i))//' KN=.. KS=..')
               return
            end if
         end do
         ! sections, masses
         nd%mass(1:nn) = 0.0_wp
         nd%inertia(1:nn) = 0.0_wp
         do g = 1, ng
            do j = work%gstart(g), work%gstart(g + 1) - 1
               e = work%gidx(j)
               el%young(e) = work%gprops(g)%young
               el%area(e) = el%thick(e)
               el%inertia(e) = el%thick(e)**3/12.0_wp
               l = el%length0(e)
               mh = 0.5_wp*work%gprops(g)%density*el%area(e)*l
               a = el%n1(e)
               b = el%n2(e)
               nd%mass(a) = nd%mass(a) + mh
               nd%mass(b) = nd%mass(b) + mh
               nd%inertia(a) = nd%inertia(a) + mh*l*l/12.0_wp
               nd%inertia(b) = nd%inertia(b) + mh*l*l/12.0_wp
            end do
         end do
         if (allocated(work%m_in)) deallocate (work%m_in, work%i_in, work%omega2)
         allocate (work%m_in(max(1_ip, nn)), work%i_in(max(1_ip, nn)), work%omega2(max(1_ip, nn)))
         work%m_in(1:nn) = nd%mass(1:nn)
         work%i_in(1:nn) = nd%inertia(1:nn)
         ! frequency bounds (mass-normalised Gershgorin row sums): translation
         ! axial 2 EA/L, transverse 2 x 12 EI/L^3, coupling to rotations 2 x 6 EI/L^2;
         ! rotation 4 EI/L + 2 EI/L, coupling to translations 2 x 6 EI/L^2
         allocate (wt(max(1_ip, nn)), wr(max(1_ip, nn)))
         wt = 0.0_wp
         wr = 0.0_wp
         do e = 1, el%n
            a = el%n1(e)
            b = el%n2(e)
            l = el%length0(e)
            ea = el%young(e)*el%area(e)/l
            ei = el%young(e)*el%inertia(e)/l
            mmin = min(nd%mass(a), nd%mass(b))
            jmin = min(nd%inertia(a), nd%inertia(b))
            if (mmin <= 0.0_wp .or. jmin <= 0.0_wp) cycle
            mh = (2.0_wp*ea + 24.0_wp*ei/(l*l))/mmin + 12.0_wp*ei/l/sqrt(mmin*jmin)
            wt(a) = wt(a) + mh
            wt(b) = wt(b) + mh
            mh = 6.0_wp*ei/jmin + 12.0_wp*ei/l/sqrt(mmin*jmin)
            wr(a) = wr(a) + mh
            wr(b) = wr(b) + mh
         end do
         do i = 1, it%n
            a = it%node(i)
            if (nd%mass(a) > 0.0_wp) wt(a) = wt(a) + 2.0_wp*max(work%kn(i), work%ks(i))/nd%mass(a)
         end do
         work%omega2 = max(wt, wr)
      end associate
   end subroutine structure_prepare

   !> Critical time step of the nodes (without FRACTION); huge if none bounds it.
   real(wp) function structure_timestep(st, work) result(dt)
      type(structure_t), intent(in) :: st
      type(structure_work_t), intent(in) :: work
      integer(ip) :: k
      dt = huge(1.0_wp)
      if (.not. work%active) return
      do k = 1, st%nodes%n
         if (st%nodes%fix(k) == ior(ior(sfix_x, sfix_y), sfix_r)) cycle
         if (work%omega2(k) <= 0.0_wp) cycle
         dt = min(dt, 2.0_wp/sqrt(work%omega2(k)))
      end do
   end function structure_timestep

   !> Mass scaling (MSCALE): raise the inertia of every node whose critical
   !> step (times frac) is below dt so that it no longer limits the step.
   subroutine structure_fit_masses(st, work, dt, frac)
      type(structure_t), intent(in) :: st
      type(structure_work_t), intent(inout) :: work
      real(wp), intent(in) :: dt, frac
      integer(ip) :: k
      real(wp) :: dtn, f
      if (.not. work%active) return
      do k = 1, st%nodes%n
         if (work%omega2(k) <= 0.0_wp) cycle
         dtn = frac*2.0_wp/sqrt(work%omega2(k))
         if (dtn >= dt) cycle
         f = (dt/dtn)**2
         work%m_in(k) = work%m_in(k)*f
         work%i_in(k) = work%i_in(k)*f
         work%omega2(k) = work%omega2(k)/f
      end do
   end subroutine structure_fit_masses

   !> Keep a copy of the moving node state before a step (as motion_save
   !> does for blocks and gridpoints), so that a numerical failure in the
   !> step can restore the last good state. Interface and element forces
   !> change only in the force pass, after the failure checks.
   subroutine structure_save(st, work)
      type(structure_t), intent(in) :: st
      type(structure_work_t), intent(inout) :: work
      integer(ip) :: k, n
      n = st%nodes%n
      work%nsaved = 0
      if (.not. work%active) return
      if (allocated(work%saved)) then
         if (size(work%saved, 2) < n) deallocate (work%saved)
      end if
      if (.not. allocated(work%saved)) allocate (work%saved(8, max(1_ip, n)))
      associate (nd => st%nodes)
         do k = 1, n
            work%saved(:, k) = [nd%x(k), nd%y(k), nd%vx(k), nd%vy(k), nd%vr(k), nd%ux(k), &
                                nd%uy(k), nd%rot(k)]
         end do
      end associate
      work%nsaved = n
   end subroutine structure_save

   !> Undo a step: the node state as `structure_save` found it.
   subroutine structure_restore(st, work)
      type(structure_t), intent(inout) :: st
      type(structure_work_t), intent(in) :: work
      if (.not. allocated(work%saved)) return   ! nothing saved
      associate (nd => st%nodes, m => min(work%nsaved, st%nodes%n))
         nd%x(1:m) = work%saved(1, 1:m); nd%y(1:m) = work%saved(2, 1:m)
         nd%vx(1:m) = work%saved(3, 1:m); nd%vy(1:m) = work%saved(4, 1:m)
         nd%vr(1:m) = work%saved(5, 1:m); nd%ux(1:m) = work%saved(6, 1:m)
         nd%uy(1:m) = work%saved(7, 1:m); nd%rot(1:m) = work%saved(8, 1:m)
      end associate
   end subroutine structure_restore

   !> One central-difference step of every node (as gridpoint_motion): force
   !> sums of the last step plus gravity on the real mass plus the applied
   !> load; held directions keep their velocity; DAMP LOCAL's -aloc |F|
   !> sign(v) per degree of freedom (aloc 0 otherwise). Returns in `sa%res` the
   !> largest unbalanced force and its node, kinetic-energy change and damping
   !> energy (no travel: the nodes are not searched for contacts).
   subroutine structure_motion(st, work, sa)
      type(structure_t), intent(inout) :: st
      type(structure_work_t), intent(in) :: work
      type(stage_args_t), intent(inout) :: sa
      integer(ip) :: k
      real(wp) :: m, j, fx, fy, fm, vx0, vy0, vr0, vx, vy, vr, f
      sa%res = motion_result_t()
      if (.not. work%active) return
      associate (nd => st%nodes)
         do k = 1, nd%n
            m = work%m_in(k)
            j = work%i_in(k)
            if (m <= 0.0_wp .or. j <= 0.0_wp) cycle
            fx = nd%fx(k) + nd%mass(k)*sa%ms%grav(1) + nd%lx(k)
            fy = nd%fy(k) + nd%mass(k)*sa%ms%grav(2) + nd%ly(k)
            fm = nd%fm(k)
            vx0 = nd%vx(k); vy0 = nd%vy(k); vr0 = nd%vr(k)
            vx = vx0; vy = vy0; vr = vr0
            if (iand(nd%fix(k), sfix_x) == 0) then
               vx = damped_velocity(vx0, fx, m, sa%ms%dt, sa%ms%aloc, sa%ms%con1, sa%ms%con2)
            else
               fx = 0.0_wp
            end if
            if (iand(nd%fix(k), sfix_y) == 0) then
               vy = damped_velocity(vy0, fy, m, sa%ms%dt, sa%ms%aloc, sa%ms%con1, sa%ms%con2)
            else
               fy = 0.0_wp
            end if
            if (iand(nd%fix(k), sfix_r) == 0) &
               vr = damped_velocity(vr0, fm, j, sa%ms%dt, sa%ms%aloc, sa%ms%con1, sa%ms%con2)
            f = hypot(fx, fy)
            if (.not. (f <= sa%res%unbal)) then      ! also catches NaN
               sa%res%unbal = f
               sa%res%at = k
            end if
            sa%res%dke = sa%res%dke + 0.5_wp*m*abs(vx*vx + vy*vy - vx0*vx0 - vy0*vy0) + &
                  0.5_wp*j*abs(vr*vr - vr0*vr0)
            sa%res%edamp = sa%res%edamp + sa%ms%alpha*sa%ms%dt*0.25_wp* &
                           (m*((vx0 + vx)**2 + (vy0 + vy)**2) + j*(vr0 + vr)**2)
            nd%vx(k) = vx; nd%vy(k) = vy; nd%vr(k) = vr
            nd%x(k) = nd%x(k) + vx*sa%ms%dt
            nd%y(k) = nd%y(k) + vy*sa%ms%dt
            nd%ux(k) = nd%ux(k) + vx*sa%ms%dt
            nd%uy(k) = nd%uy(k) + vy*sa%ms%dt
            nd%rot(k) = nd%rot(k) + vr*sa%ms%dt
         end do
      end associate
   end subroutine structure_motion

   !> Force sums of the nodes: beam elements (one call per material group)
   !> and interfaces, whose reactions go to the blocks / gridpoints. With
   !> sa%ms%dt = 0 the interfaces only re-assemble their present forces.
   subroutine structure_force_pass(st, geo, work, sa)
      type(structure_t), intent(inout) :: st
      type(geometry_t), intent(inout) :: geo
      type(structure_work_t), intent(in) :: work
      type(stage_args_t), intent(in) :: sa
      integer :: g
      integer(ip) :: n
      if (.not. work%active) return
      n = st%nodes%n
      st%nodes%fx(1:n) = 0.0_wp
      st%nodes%fy(1:n) = 0.0_wp
      st%nodes%fm(1:n) = 0.0_wp
      do g = 1, work%ngroup
         call work%models(g)%model%forces(st, work%gidx(work%gstart(g):work%gstart(g + 1) - 1), &
                                          work%gprops(g))
      end do
      call interface_pass(st, geo, work, sa%ms%dt)
   end subroutine structure_force_pass

   !> Interface kernel (module header).
   subroutine interface_pass(st, geo, work, dt)
      type(structure_t), intent(inout) :: st
      type(geometry_t), intent(inout) :: geo
      type(structure_work_t), intent(in) :: work
      real(wp), intent(in) :: dt
      integer(ip) :: i, k, b, c, c2, ga, gb
      real(wp) :: s, px, py, nx, ny, vx, vy, dvx, dvy, dun, dus, fn, fs, fmax, fx, fy, coh, tens
      associate (nd => st%nodes, it => st%interfaces, bl => geo%blocks, co => geo%corners, &
                 gp => geo%gridpoints)
         do i = 1, it%n
            b = it%block(i)
            k = it%node(i)
            if (b < 1 .or. b > bl%n) cycle
            if (.not. bl%live(b)) cycle
            c = it%edge(i)
            if (.not. co%live(c)) cycle
            call locate(nd%x(k), nd%y(k), c, s, px, py, nx, ny)
            it%edge(i) = c
            it%x(i) = px; it%y(i) = py; it%nx(i) = nx; it%ny(i) = ny
            c2 = co%next(c)
            ga = co%gp(c)
            gb = co%gp(c2)
            if (ga > 0 .and. gb > 0) then
               vx = (1.0_wp - s)*gp%vx(ga) + s*gp%vx(gb)
               vy = (1.0_wp - s)*gp%vy(ga) + s*gp%vy(gb)
            else
               vx = bl%vx(b) - bl%vr(b)*(py - bl%yc(b))
               vy = bl%vy(b) + bl%vr(b)*(px - bl%xc(b))
            end if
            dvx = nd%vx(k) - vx
            dvy = nd%vy(k) - vy
            dun = (dvx*nx + dvy*ny)*dt
            dus = (-dvx*ny + dvy*nx)*dt
            it%un(i) = it%un(i) + dun
            it%us(i) = it%us(i) + dus
            coh = work%coh(i)
            tens = work%tens(i)
            if (iand(it%flags(i), iface_broken) /= 0) then
               coh = 0.0_wp
               tens = 0.0_wp
            end if
            fn = -work%kn(i)*it%un(i)
            if (fn < -tens) then
               if (tens > 0.0_wp) it%flags(i) = ior(it%flags(i), iface_broken)
               fn = 0.0_wp
               coh = 0.0_wp
            end if
            fs = it%fs(i) - work%ks(i)*dus
            fmax = coh + work%fric(i)*max(fn, 0.0_wp)
            it%flags(i) = iand(it%flags(i), not(iface_slip))
            if (abs(fs) > fmax) then
               fs = sign(fmax, fs)
               it%flags(i) = ior(it%flags(i), iface_slip)
            end if
            it%fn(i) = fn
            it%fs(i) = fs
            fx = fn*nx - fs*ny
            fy = fn*ny + fs*nx
            nd%fx(k) = nd%fx(k) + fx
            nd%fy(k) = nd%fy(k) + fy
            if (ga > 0 .and. gb > 0) then
               call add_shared_force(gp%fx, gp%fy, ga, gb, s, -fx, -fy)
            else
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, px - bl%xc(b), py - bl%yc(b), &
                                    -fx, -fy)
            end if
         end do
      end associate
   contains
      !> Project (x, y) on the edge starting at corner c; step once to the
      !> neighbouring edge when the projection falls beyond an end of it.
      subroutine locate(x, y, c, s, px, py, nx, ny)
         real(wp), intent(in) :: x, y
         integer(ip), intent(inout) :: c
         real(wp), intent(out) :: s, px, py, nx, ny
         integer(ip) :: cn
         real(wp) :: sn
         s = edge_param(c, x, y)
         if (s < 0.0_wp .or. s > 1.0_wp) then
            cn = merge(geo%corners%prev(c), geo%corners%next(c), s < 0.0_wp)
            sn = edge_param(cn, x, y)
            ! only onto an edge turning less than 60 degrees from this one:
            ! past a sharp corner of the periphery (a horseshoe's arch ending
            ! on the joint below its springline) the next edge is a joint
            ! face; measured along its normal the node's drift along the
            ! wall read as an opening and broke the interface (the end
            ! element then carried nothing)
            if (sn >= 0.0_wp .and. sn <= 1.0_wp .and. gentle_turn(c, cn)) then
               c = cn
               s = sn
            end if
         end if
         s = min(max(s, 0.0_wp), 1.0_wp)
         associate (co => geo%corners)
            cn = co%next(c)
            px = co%x(c) + s*(co%x(cn) - co%x(c))
            py = co%y(c) + s*(co%y(cn) - co%y(c))
            ! clockwise ring: the block lies right of the edge, outward is left
            nx = -(co%y(cn) - co%y(c))
            ny = co%x(cn) - co%x(c)
            sn = hypot(nx, ny)
            nx = nx/sn
            ny = ny/sn
         end associate
      end subroutine locate
      !> Edges c1 and c2 of one block (neighbours) turn by less than 60 degrees.
      logical function gentle_turn(c1, c2) result(yes)
         integer(ip), intent(in) :: c1, c2
         real(wp) :: ax, ay, bx, by
         associate (co => geo%corners)
            ax = co%x(co%next(c1)) - co%x(c1); ay = co%y(co%next(c1)) - co%y(c1)
            bx = co%x(co%next(c2)) - co%x(c2); by = co%y(co%next(c2)) - co%y(c2)
         end associate
         yes = ax*bx + ay*by > 0.5_wp*hypot(ax, ay)*hypot(bx, by)
      end function gentle_turn
      real(wp) function edge_param(c, x, y) result(t)
         integer(ip), intent(in) :: c
         real(wp), intent(in) :: x, y
         integer(ip) :: cn
         real(wp) :: dx, dy
         associate (co => geo%corners)
            cn = co%next(c)
            dx = co%x(cn) - co%x(c)
            dy = co%y(cn) - co%y(c)
            t = ((x - co%x(c))*dx + (y - co%y(c))*dy)/(dx*dx + dy*dy)
         end associate
      end function edge_param
   end subroutine interface_pass

end module structure_mechanics
