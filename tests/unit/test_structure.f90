!> Structural elements (model_structures, structure_models, structure_mechanics,
!> structure_generate, commands_structure): closed-form beams and a ring solved
!> by the explicit structure kernels alone (dynamic relaxation with mass-
!> proportional damping), the element-model factory, and the STRUCTURE / PRINT
!> STE STC LM commands with their errors.
!>
!> Closed forms (Euler-Bernoulli beam, exact at the nodes for cubic elements):
!>   cantilever, end load P:          tip deflection P L^3 / (3 E I)
!>   simply supported, centre load P: centre deflection P L^3 / (48 E I)
!>   ring (polygon of n nodes, radius r) under uniform external pressure p
!>   (node loads p x chord): thrust N = p r, radial displacement p r^2 / (E A).
!> Tolerances: 1e-3 relative (the loads are small, deflection / span ~ 1e-4, so
!> the geometric non-linearity of the co-rotational frame is ~1e-8; the rest is
!> the residual of the damped relaxation).
program test_structure
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_is_finite
   use core_kinds, only: wp, ip
   use model_properties, only: prop_bulk, prop_density, prop_shear
   use core_error, only: error_t
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_structures, only: structure_t, structure_add_node, structure_add_element, &
                               sfix_x, sfix_y, sfix_r
   use structure_models, only: beam_model_t, beam_model_create, beam_model_names
   use structure_mechanics, only: structure_work_t, structure_prepare, structure_timestep, &
                                  structure_motion, structure_force_pass, structure_young
   use core_motion, only: motion_step, stage_args_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, testing_finish
   use plot_scene, only: item_polyline, purple
   implicit none

   real(wp), parameter :: pi = 3.14159265358979323846_wp
   real(wp), parameter :: bulk = 2.0e3_wp, shear = 1.0e3_wp, thick = 0.1_wp
   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_factory()
   call test_cantilever()
   call test_simple_beam()
   call test_ring()
   call test_commands()
   call testing_finish()

contains

   subroutine check_rel(actual, expected, tol, label)
      real(wp), intent(in) :: actual, expected, tol
      character(len=*), intent(in) :: label
      character(len=120) :: text
      write (text, '(2(a,es14.6))') ' actual=', actual, ' expected=', expected
      call check(abs(actual - expected) <= tol*abs(expected), label//trim(text))
   end subroutine check_rel

   !> Every listed model can be built; an unknown name is an error naming them.
   subroutine test_factory()
      class(beam_model_t), allocatable :: m
      type(error_t), allocatable :: error
      integer :: i
      do i = 1, size(beam_model_names)
         call beam_model_create(trim(beam_model_names(i)), m, error)
         call check(.not. allocated(error) .and. allocated(m), 'factory builds '//beam_model_names(i))
      end do
      call beam_model_create('PLASTIC', m, error)
      call check(allocated(error), 'factory refuses an unknown model')
      if (allocated(error)) call check(index(error%message, 'ELASTIC') > 0, &
                                       'factory error names the known models')
      ! E = 9KG/(3K+G): K = 2000, G = 1000 -> 18e6/7000
      call check_rel(structure_young(bulk, shear), 18.0e6_wp/7.0e3_wp, 1.0e-14_wp, 'E from K, G')
   end subroutine test_factory

   subroutine materials(mats)
      type(material_table_t), intent(out) :: mats
      call mats%set(1, prop_density, 1.0_wp)
      call mats%set(1, prop_bulk, bulk)
      call mats%set(1, prop_shear, shear)
   end subroutine materials

   !> A straight beam of nel elements from (0,0) to (span,0).
   subroutine straight_beam(st, nel, span)
      type(structure_t), intent(out) :: st
      integer(ip), intent(in) :: nel
      real(wp), intent(in) :: span
      integer(ip) :: k, id, prev, e
      prev = 0
      do k = 0, nel
         call structure_add_node(st, span*real(k, wp)/real(nel, wp), 0.0_wp, 1_ip, id)
         if (k > 0) call structure_add_element(st, prev, id, 1_ip, thick, e)
         prev = id
      end do
   end subroutine straight_beam

   !> Damped explicit relaxation of the structure alone: alpha critical for
   !> the lowest mode (omega1), dt half the critical step.
   subroutine relax(st, omega1, nstep)
      type(structure_t), intent(inout) :: st
      real(wp), intent(in) :: omega1
      integer, intent(in) :: nstep
      type(structure_work_t) :: work
      type(material_table_t) :: mats
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      real(wp) :: dt
      type(stage_args_t) :: sa
      integer :: i
      call materials(mats)
      call structure_prepare(st, mats, work, error)
      call check(.not. allocated(error), 'structure_prepare succeeds')
      if (allocated(error)) return
      dt = 0.5_wp*structure_timestep(st, work)
      sa%ms = motion_step([0.0_wp, 0.0_wp], dt, 2.0_wp*omega1, 0.0_wp)
      do i = 1, nstep
         call structure_force_pass(st, geo, work, sa)
         call structure_motion(st, work, sa)
      end do
      call structure_force_pass(st, geo, work, sa)
   end subroutine relax

   subroutine test_cantilever()
      type(structure_t) :: st
      real(wp) :: e, inertia, p, span, omega1
      span = 1.0_wp
      p = 1.0e-4_wp
      call straight_beam(st, 10_ip, span)
      st%nodes%fix(1) = ior(ior(sfix_x, sfix_y), sfix_r)
      st%nodes%ly(st%nodes%n) = -p
      e = structure_young(bulk, shear)
      inertia = thick**3/12.0_wp
      ! first cantilever mode 3.516 sqrt(EI / (rho A L^4))
      omega1 = 3.516_wp*sqrt(e*inertia/(1.0_wp*thick*span**4))
      call relax(st, omega1, 40000)
      call check_rel(-st%nodes%uy(st%nodes%n), p*span**3/(3.0_wp*e*inertia), 1.0e-3_wp, &
                     'cantilever tip deflection = P L^3 / 3EI')
      ! tip rotation P L^2 / 2EI (clockwise: negative)
      call check_rel(-st%nodes%rot(st%nodes%n), p*span**2/(2.0_wp*e*inertia), 1.0e-3_wp, &
                     'cantilever tip rotation = P L^2 / 2EI')
      ! root moment P L, shear P (element 1)
      call check_rel(abs(st%elements%m1(1)), p*span, 1.0e-3_wp, 'cantilever root moment = P L')
      call check_rel(abs(st%elements%shear(1)), p, 1.0e-3_wp, 'cantilever shear = P')
   end subroutine test_cantilever

   subroutine test_simple_beam()
      type(structure_t) :: st
      real(wp) :: e, inertia, p, span, omega1
      span = 2.0_wp
      p = 1.0e-4_wp
      call straight_beam(st, 10_ip, span)
      st%nodes%fix(1) = ior(sfix_x, sfix_y)
      st%nodes%fix(st%nodes%n) = sfix_y
      st%nodes%ly(6) = -p
      e = structure_young(bulk, shear)
      inertia = thick**3/12.0_wp
      omega1 = pi**2*sqrt(e*inertia/(1.0_wp*thick*span**4))
      call relax(st, omega1, 40000)
      call check_rel(-st%nodes%uy(6), p*span**3/(48.0_wp*e*inertia), 1.0e-3_wp, &
                     'simple beam centre deflection = P L^3 / 48EI')
      ! support rotation P L^2 / 16EI
      call check_rel(-st%nodes%rot(1), p*span**2/(16.0_wp*e*inertia), 1.0e-3_wp, &
                     'simple beam end rotation = P L^2 / 16EI')
   end subroutine test_simple_beam

   subroutine test_ring()
      type(structure_t) :: st
      integer(ip), parameter :: n = 24
      real(wp) :: r, p, chord, a, e, omega1, ur
      integer(ip) :: k, id, e_id, first, prev
      r = 1.0_wp
      p = 1.0e-2_wp
      chord = 2.0_wp*r*sin(pi/real(n, wp))
      prev = 0
      first = 0
      do k = 1, n
         a = 2.0_wp*pi*real(k - 1, wp)/real(n, wp)
         call structure_add_node(st, r*cos(a), r*sin(a), 1_ip, id)
         st%nodes%lx(id) = -p*chord*cos(a)
         st%nodes%ly(id) = -p*chord*sin(a)
         if (k == 1) first = id
         if (k > 1) call structure_add_element(st, prev, id, 1_ip, thick, e_id)
         prev = id
      end do
      call structure_add_element(st, prev, first, 1_ip, thick, e_id)
      e = structure_young(bulk, shear)
      ! breathing mode of a ring: omega^2 = E / (rho r^2)
      omega1 = sqrt(e/(1.0_wp*r*r))
      call relax(st, omega1, 20000)
      do k = 1, n
         call check_rel(-st%elements%axial(k), p*r, 1.0e-3_wp, 'ring thrust = p r')
      end do
      ur = -(st%nodes%ux(1)*st%nodes%x(1) + st%nodes%uy(1)*st%nodes%y(1))/r
      call check_rel(ur, p*r*r/(e*thick), 1.0e-3_wp, 'ring radial displacement = p r^2 / EA')
      call check(maxval(abs(st%elements%m1(1:n))) <= 1.0e-6_wp*p*r*r, 'ring carries no moment')
   end subroutine test_ring

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   !> STRUCTURE around a square-ish opening of a rigid block assembly; errors.
   subroutine test_commands()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call run('STRUCTURE 0 0 7.5 1.1 24 1 .1')
      call check(lines_contain(lines, 'no BLOCK'), 'STRUCTURE before BLOCK is refused')
      call run('ROUND 0.01')
      call run('BLOCK -3 -3 -3 3 3 3 3 -3')
      call run('CRACK -10 0 10 0')
      call run('CRACK 0 -10 0 10')
      call run('TUNNEL 0 0 1 24')
      call run('DELETE -.49 .49 -.49 .49')
      call run('STRUCTURE 0 0 7.5 0.5 24 1 .1')
      call check(lines_contain(lines, 'no block edge'), 'STRUCTURE with rrange short of the wall is refused')
      call check(.not. allocated(session%model%structures), 'refused STRUCTURE creates nothing')
      call run('PRINT STE')
      call check(lines_contain(lines, 'no structural elements'), 'PRINT STE without structures')
      call run('STRUCTURE 0 0 7.5 1.1 24 1 .1')
      call check(allocated(session%model%structures), 'STRUCTURE creates the structure lists')
      if (.not. allocated(session%model%structures)) return
      associate (st => session%model%structures)
         call check(st%nodes%n == 24 .and. st%elements%n == 24 .and. st%interfaces%n == 24, &
                    'closed ring: 24 nodes, elements, interfaces')
         ! node 1 on the edge midpoint at 7.5 degrees: r = cos(7.5 deg)
         call check_rel(hypot(st%nodes%x(1), st%nodes%y(1)), cos(7.5_wp*pi/180.0_wp), 1.0e-9_wp, &
                        'node 1 on the tunnel wall')
         ! interface normal points from the rock into the opening (towards the centre)
         call check(st%interfaces%nx(1)*st%nodes%x(1) + st%interfaces%ny(1)*st%nodes%y(1) < 0.0_wp, &
                    'interface normal points out of the block')
      end associate
      call run('STRUCTURE 0 0 0 1.1 6 1 .1 90')
      call check(session%model%structures%nodes%n == 24 + 7 .and. &
                 session%model%structures%elements%n == 24 + 6, 'open arc: npoin + 1 nodes')
      call test_plot_structure(30, 31)
      call run('PRINT STE STC LM')
      call check(lines_contain(lines, 'Structural elements') .and. &
                 lines_contain(lines, 'interfaces') .and. lines_contain(lines, 'lumped masses'), &
                 'PRINT STE STC LM print three tables')
      ! a rigid assembly: CYCLE without interface stiffness is refused
      call run('PROP MAT=1 DENS=1 K=2E3 G=1E3 JKN=1E3 JKS=1E3')
      call run('CYCLE 1')
      call check(lines_contain(lines, 'has no normal stiffness: give PROPERTY MAT=1 KN=..'), &
                 'CYCLE without interface KN names the property')
      call check(session%model%mech%step == 0, 'refused CYCLE takes no step')
      call run('PROP MAT=1 KN=1E3 KS=1')
      call run('CYCLE 5')
      call check(session%model%mech%step == 5, 'rigid model with structures cycles')
      call test_failure_restore()
   end subroutine test_commands

   !> PLOT STRUCT: one thick purple line per element in the picture (clipped
   !> items; the legend sample is not clipped), the counts in the
   !> legend, and the layer named in the picture's title.
   subroutine test_plot_structure(nel, nnode)
      integer, intent(in) :: nel, nnode
      integer :: j, nline
      character(len=16) :: t1, t2
      call run('PLOT BLOCKS STRUCT')
      call check(index(session%plot%scene%what, 'STRUCT') > 0, 'PLOT STRUCT is drawn')
      write (t1, '(i0)') nel
      write (t2, '(i0)') nnode
      call check(has_legend('structural elements ('//trim(t1)//')'), &
                 'PLOT STRUCT legend counts the elements')
      call check(has_legend('lumped masses ('//trim(t2)//')'), 'PLOT STRUCT legend counts the nodes')
      nline = 0
      do j = 1, session%plot%scene%nitem
         associate (it => session%plot%scene%items(j))
            if (it%kind == item_polyline .and. it%clip .and. it%width == 3.0_wp .and. &
                all(it%colour == purple)) nline = nline + 1
         end associate
      end do
      call check(nline == nel, 'PLOT STRUCT draws one line per element')
   end subroutine test_plot_structure

   logical function has_legend(text)
      character(len=*), intent(in) :: text
      integer :: j
      has_legend = .false.
      do j = 1, session%plot%scene%nlegend
         if (session%plot%scene%legend(j)%text == text) has_legend = .true.
      end do
   end function has_legend

   !> A numerical failure restores the last good step, structure nodes
   !> included: an infinite load on node 1 makes its unbalanced force non-
   !> finite in the next step; the cycle stops with the error and every node
   !> is back (bit for bit) where it was before that step, all finite.
   subroutine test_failure_restore()
      real(wp), allocatable :: before(:, :)
      integer(ip) :: n, k
      logical :: same
      call run('DAMP AUTO')
      call run('CYCLE 5')
      associate (nd => session%model%structures%nodes)
         n = nd%n
         allocate (before(8, n))
         do k = 1, n
            before(:, k) = [nd%x(k), nd%y(k), nd%vx(k), nd%vy(k), nd%vr(k), nd%ux(k), &
                            nd%uy(k), nd%rot(k)]
         end do
         nd%lx(1) = ieee_value(1.0_wp, ieee_positive_inf)
      end associate
      call run('CYCLE 3')
      call check(lines_contain(lines, 'numerical failure: structure node 1'), &
                 'an infinite node load stops the cycle with a numerical failure of node 1')
      call check(session%model%mech%step == 10, 'the failing step is not counted')
      associate (nd => session%model%structures%nodes)
         same = .true.
         do k = 1, n
            same = same .and. all([nd%x(k), nd%y(k), nd%vx(k), nd%vy(k), nd%vr(k), nd%ux(k), &
                                   nd%uy(k), nd%rot(k)] == before(:, k))
         end do
         call check(same, 'structure nodes restored to the last good step')
         nd%lx(1) = 0.0_wp
      end associate
      call run('CYCLE 2')
      call check(session%model%mech%step == 12, 'the restored model cycles on')
      call check(all(ieee_is_finite(session%model%structures%nodes%x(1:n))), &
                 'restored node positions stay finite')
   end subroutine test_failure_restore

end program test_structure
