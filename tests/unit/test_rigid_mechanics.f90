!> Rigid-block mechanics against closed-form answers (issue 4). Each case
!> builds a small model through the command interpreter, cycles, and reads
!> the histories. Units SI; g = 10 m/s^2.
program test_rigid_mechanics
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use contact_kinematics, only: contact_overlap_limit
   use testing, only: check, check_close, testing_finish
   use testing_session, only: new_session => session_new_quiet, run => session_lines
   use commands_session, only: session_t, session_init, session_execute_line
   implicit none
   real(wp), parameter :: g = 10.0_wp
   real(wp), parameter :: tan_a = 0.5_wp               ! incline: tan(alpha) = 0.5
   real(wp) :: sin_a, cos_a

   sin_a = tan_a/sqrt(1.0_wp + tan_a**2)
   cos_a = 1.0_wp/sqrt(1.0_wp + tan_a**2)
   call incline_slides()
   call incline_sticks()
   call damped_to_rest()
   call toppling()
   call impact()
   call overlap_too_great()
   call testing_finish()

contains

   !> A 2 m x 1 m block (block 'B') on a fixed base; the incline is made by
   !> tilting gravity: g = 10 (sin a, -cos a), tan a = 0.5.
   subroutine block_on_base(s, fric)
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: fric
      character(len=80) :: grav
      write (grav, '(a,2(1x,es22.15))') 'GRAVITY', g*sin_a, -g*cos_a
      call run(s, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,2 20,2 20,0', &
                   'SPLIT 0,1 20,1', 'SPLIT 9,1 9,2', 'SPLIT 11,1 11,2', &
                   'DELETE 0,9 1,2', 'DELETE 11,20 1,2', 'FIX 0,20 0,1', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC='//fric, grav])
   end subroutine block_on_base

   !> Least-squares slope of history variable `iv` against time for samples
   !> with t in [t0, t1].
   real(wp) function hist_slope(s, iv, t0, t1) result(slope)
      type(session_t), intent(in) :: s
      integer, intent(in) :: iv
      real(wp), intent(in) :: t0, t1
      integer :: k, n
      real(wp) :: st, sv, stt, stv, t, v
      n = 0; st = 0; sv = 0; stt = 0; stv = 0
      do k = 1, int(s%model%hist%nsample)
         t = s%model%hist%time(k)
         if (t < t0 .or. t > t1) cycle
         v = s%model%hist%values(iv, k)
         n = n + 1
         st = st + t; sv = sv + v; stt = stt + t*t; stv = stv + t*v
      end do
      slope = (n*stv - st*sv)/(n*stt - st*st)
   end function hist_slope

   !> Friction 0.2 < tan a: the block slides with a = g (sin a - mu cos a)
   !> = 2.6833 m/s^2. Reference: Newton's law on an incline; tolerance 2 %
   !> (issue 4), measured as the least-squares slope of the corner velocity.
   subroutine incline_slides()
      type(session_t) :: s
      real(wp) :: a, expected
      call new_session(s)
      call block_on_base(s, '0.2')
      call run(s, [character(len=40) :: 'HIST XVEL 11,2 NCYC 10', 'CYCLE 5000'])
      call check(s%nerrors == 0, 'incline: the deck runs without errors')
      expected = g*(sin_a - 0.2_wp*cos_a)
      a = hist_slope(s, 1, 0.1_wp*s%model%mech%time, s%model%mech%time)
      print '(a,f10.6,a,f10.6)', '  incline: a = ', a, ', closed form ', expected
      call check_close(a, expected, 0.02_wp, 'incline: a = g (sin a - mu cos a) within 2 %')
   end subroutine incline_slides

   !> Friction 0.6 > tan a: the block sticks. Reference: static equilibrium.
   !> Gravity switched on at once makes the normal force oscillate (between
   !> 0 and twice its mean without damping), and the block slips a little
   !> while the normal force is low, so the case runs with DAMP AUTO; the
   !> elastic shear of the joint is m g sin a / (ks L) = 5000*4.47/2e9 =
   !> 1.1e-5 m, sliding would travel metres. Tolerances: total displacement
   !> below 1e-4 m, and no further motion (below 1e-7 m) over the second
   !> half of the run.
   subroutine incline_sticks()
      type(session_t) :: s
      integer :: k, n
      real(wp) :: umax, creep
      call new_session(s)
      call block_on_base(s, '0.6')
      call run(s, [character(len=40) :: 'DAMP AUTO', 'HIST XDIS 11,2 NCYC 10', 'CYCLE 5000'])
      umax = 0.0_wp
      n = int(s%model%hist%nsample)
      do k = 1, n
         umax = max(umax, abs(s%model%hist%values(1, k)))
      end do
      creep = abs(s%model%hist%values(1, n) - s%model%hist%values(1, n/2))
      print '(a,es12.4,a,es12.4,a)', '  sticking: largest displacement ', umax, &
         ' m, second-half motion ', creep, ' m'
      call check(s%nerrors == 0, 'sticking: the deck runs without errors')
      call check(umax < 1.0e-4_wp, 'sticking: friction above tan(a) holds the block (|ux| < 1e-4 m)')
      call check(creep < 1.0e-7_wp, 'sticking: no further slip once settled')
      call check(s%model%mech%time > 1.0_wp, 'sticking: more than 1 s of problem time simulated')
   end subroutine incline_sticks

   !> A block dropped onto a flat base with zero gap under DAMP AUTO comes to
   !> rest. Reference: static equilibrium (unbalanced force 0, velocity 0);
   !> tolerance: unbalanced force below 1e-4 of the weight after 1000 cycles.
   subroutine damped_to_rest()
      type(session_t) :: s
      real(wp) :: weight
      call new_session(s)
      call run(s, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,2 20,2 20,0', &
                   'SPLIT 0,1 20,1', 'SPLIT 9,1 9,2', 'SPLIT 11,1 11,2', &
                   'DELETE 0,9 1,2', 'DELETE 11,20 1,2', 'FIX 0,20 0,1', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC=0.5', &
                   'GRAVITY 0 -10', 'DAMP AUTO', 'HIST YVEL 10,2 UNBAL', 'CYCLE 1000'])
      weight = 2500.0_wp*2.0_wp*g
      call check(s%nerrors == 0, 'rest: the deck runs without errors')
      call check(s%model%mech%unbalanced < 1.0e-4_wp*weight, &
                 'rest: unbalanced force below 1e-4 of the weight after 1000 cycles')
      call check(abs(s%model%hist%values(1, s%model%hist%nsample)) < 1.0e-5_wp, &
                 'rest: velocity below 1e-5 m/s')
   end subroutine damped_to_rest

   !> A 1 m wide, 4 m tall block on a rough base (friction 1) under gravity
   !> tilted by a. Reference: it topples when tan a > b/h = 0.25 and stands
   !> when tan a < 0.25 (moment of the weight about the downhill corner).
   !> Cases: tan a = 0.364 (20 deg) topples: rotation beyond 0.3 rad;
   !> tan a = 0.176 (10 deg) stands: rotation below 1e-3 rad.
   subroutine toppling()
      type(session_t) :: s
      real(wp) :: deg(2), rot
      logical :: topples
      integer :: k, i
      character(len=80) :: grav
      deg = [20.0_wp, 10.0_wp]
      do k = 1, 2
         call new_session(s)
         write (grav, '(a,2(1x,es22.15))') 'GRAVITY', g*sin(deg(k)*atan(1.0_wp)/45.0_wp), &
            -g*cos(deg(k)*atan(1.0_wp)/45.0_wp)
         call run(s, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,5 20,5 20,0', &
                      'SPLIT 0,1 20,1', 'SPLIT 9,1 9,5', 'SPLIT 10,1 10,5', &
                      'DELETE 0,9 1,5', 'DELETE 10,20 1,5', 'FIX 0,20 0,1', &
                      'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=1.0', &
                      grav])
         ! cycle until the block has turned 0.3 rad (it would later hit the base)
         rot = 0.0_wp
         do i = 1, 40
            call run(s, [character(len=20) :: 'CYCLE 500'])
            rot = abs(s%model%geometry%blocks%rot(maxloc(s%model%geometry%blocks%area, 1, &
                       mask=s%model%geometry%blocks%live .and. .not. s%model%geometry%blocks%fixed)))
            if (rot > 0.3_wp .or. s%nerrors > 0) exit
         end do
         call check(s%nerrors == 0, 'toppling: the deck runs without errors')
         topples = rot > 0.3_wp
         if (k == 1) then
            call check(topples, 'toppling: b/h = 0.25 < tan 20 deg: the block topples')
         else
            call check(rot < 1.0e-3_wp, 'toppling: b/h = 0.25 > tan 10 deg: the block stands')
         end if
      end do
   end subroutine toppling

   !> A 1 m block falls 0.5 m onto a fixed base, no damping, no friction.
   !> References: free fall v = sqrt(2 g h) = 3.1623 m/s at impact; elastic
   !> contact without damping returns the kinetic energy (rebound speed =
   !> impact speed within 1 %); momentum balance over the impact: the
   !> impulse of the contact force equals m (v_after - v_before) + m g T
   !> (within 1 %).
   subroutine impact()
      type(session_t) :: s
      integer :: k, n, k0, k1
      real(wp) :: v, vin, vout, impulse, m, t0, t1
      call new_session(s)
      call run(s, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,2.5 20,2.5 20,0', &
                   'SPLIT 0,1 20,1', 'SPLIT 0,1.5 20,1.5', 'SPLIT 9.5,1.5 9.5,2.5', &
                   'SPLIT 10.5,1.5 10.5,2.5', 'DELETE 0,20 1,1.5', 'DELETE 0,9.5 1.5,2.5', &
                   'DELETE 10.5,20 1.5,2.5', 'FIX 0,20 0,1', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0', &
                   'GRAVITY 0 -10', 'HIST YVEL 10,2.5 BFY 4 NCYC 1', 'CYCLE 12000'])
      call check(s%nerrors == 0, 'impact: the deck runs without errors')
      m = 2500.0_wp
      ! impact: first sample with a contact force; rebound: first sample after
      n = int(s%model%hist%nsample)
      k0 = 0; k1 = 0
      do k = 1, n
         if (k0 == 0 .and. s%model%hist%values(2, k) > 0.0_wp) k0 = k
         if (k0 > 0 .and. k1 == 0 .and. k > k0 .and. s%model%hist%values(2, k) == 0.0_wp) k1 = k
      end do
      call check(k0 > 1 .and. k1 > k0, 'impact: the block hits the base and leaves it again')
      if (.not. (k0 > 1 .and. k1 > k0)) return
      vin = s%model%hist%values(1, k0 - 1)
      vout = s%model%hist%values(1, k1)
      v = sqrt(2.0_wp*g*0.5_wp)
      call check_close(-vin, v, 0.01_wp, 'impact: free-fall speed sqrt(2 g h) within 1 %')
      call check_close(vout, -vin, 0.01_wp, 'impact: rebound speed = impact speed within 1 %')
      impulse = 0.0_wp
      do k = k0, k1 - 1
         impulse = impulse + s%model%hist%values(2, k)*(s%model%hist%time(k + 1) - s%model%hist%time(k))
      end do
      t0 = s%model%hist%time(k0 - 1)
      t1 = s%model%hist%time(k1)
      call check_close(impulse, m*(vout - vin) + m*g*(t1 - t0), 0.01_wp, &
                       'impact: contact impulse = momentum change + m g T within 1 %')
   end subroutine impact

   !> A block pressed into its base by a load far beyond what the joint
   !> stiffness can carry within half the rounding length stops the cycle
   !> with 'Contact Overlap Too Great', the contact and its position, and the
   !> model stays as it was after the last good step.
   !> The undone model is the one a CYCLE of one step fewer leaves, bit for
   !> bit (block and corner state), though the steps before the failing one
   !> move their corners without undo copies (engine_rigid motion_work_t).
   subroutine overlap_too_great()
      type(session_t) :: s, r
      integer(ip) :: step, nb, nc, c
      character(len=20) :: line
      logical :: ok
      call overlap_scene(s)
      s%batch = .false.
      call run(s, [character(len=20) :: 'CYCLE 2000'])
      call check(s%nerrors == 1, 'overlap: CYCLE reports one error')
      step = int(s%model%mech%step, ip)
      call check(step > 0 .and. step < 2000, 'overlap: the cycle stopped early')
      ! each contact within its own tolerance (contact_overlap_limit: OVTOL
      ! 0.005 at least, d = 0.01 for these right-angled corners)
      ok = .true.
      do c = 1, s%model%geometry%contacts%n
         if (.not. s%model%geometry%contacts%live(c)) cycle
         if (-s%model%geometry%contacts%gap(c) > &
             contact_overlap_limit(s%model%geometry, c, 0.005_wp, .false.)) ok = .false.
      end do
      call check(ok, 'overlap: the model is left as after the last good step (overlaps within '// &
                 'their tolerance)')
      call overlap_scene(r)
      write (line, '(a,i0)') 'CYCLE ', step
      call run(r, [line])
      call check(r%nerrors == 0 .and. r%model%mech%step == step, 'overlap: the same steps cycle')
      associate (a => s%model%geometry%blocks, b => r%model%geometry%blocks, &
                 p => s%model%geometry%corners, q => r%model%geometry%corners)
         nb = a%n
         nc = p%n
         call check(b%n == nb .and. q%n == nc, 'overlap: the same blocks and corners')
         if (b%n /= nb .or. q%n /= nc) return
         call check(all(a%xc(1:nb) == b%xc(1:nb) .and. a%yc(1:nb) == b%yc(1:nb) .and. &
                        a%vx(1:nb) == b%vx(1:nb) .and. a%vy(1:nb) == b%vy(1:nb) .and. &
                        a%vr(1:nb) == b%vr(1:nb) .and. a%ux(1:nb) == b%ux(1:nb) .and. &
                        a%uy(1:nb) == b%uy(1:nb) .and. a%rot(1:nb) == b%rot(1:nb) .and. &
                        a%fx(1:nb) == b%fx(1:nb) .and. a%fy(1:nb) == b%fy(1:nb) .and. &
                        a%fm(1:nb) == b%fm(1:nb)), &
                    'overlap: blocks undone to the last good step bit for bit')
         call check(all(p%x(1:nc) == q%x(1:nc) .and. p%y(1:nc) == q%y(1:nc) .and. &
                        p%rx(1:nc) == q%rx(1:nc) .and. p%ry(1:nc) == q%ry(1:nc) .and. &
                        p%ux(1:nc) == q%ux(1:nc) .and. p%uy(1:nc) == q%uy(1:nc)), &
                    'overlap: corners undone to the last good step bit for bit')
      end associate
   end subroutine overlap_too_great

   !> overlap_too_great's block, loaded far beyond its joint's stiffness.
   subroutine overlap_scene(s)
      type(session_t), intent(inout) :: s
      call new_session(s)
      call run(s, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,2 20,2 20,0', &
                   'SPLIT 0,1 20,1', 'SPLIT 9,1 9,2', 'SPLIT 11,1 11,2', &
                   'DELETE 0,9 1,2', 'DELETE 11,20 1,2', 'FIX 0,20 0,1', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E6 JKS=1E6 JFRIC=0.5', &
                   'LOAD 9,11 1,2 0 -1E5'])
   end subroutine overlap_scene

end program test_rigid_mechanics
