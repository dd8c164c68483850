!> Hard cases of the rigid-block cycle stay numerically stable (label
!> `stability`, issue 4): joint stiffness contrast 1e4, acute wedges, tiny
!> rounding, one block on many smaller ones, dilation under confinement and
!> a long run. Each deck runs under DAMP AUTO to equilibrium in chunks; after
!> every chunk (`settle`):
!>   - no command error, and every block position, velocity, rotation and
!>     every contact force is finite;
!>   - bounded: the kinetic energy never exceeds the work done on the model
!>     by gravity and LOADs so far (energy balance: work = kinetic + strain
!>     + damped energy; elastic springs and damping cannot create energy),
!>     with 5 % allowance for the incremental contact law (a numerical
!>     instability grows KE exponentially and breaks this at once);
!> and at the end:
!>   - decaying: kinetic energy below 1e-8 of its largest value in the run,
!>     and the maximum unbalanced force below 1e-3 of the weight of the
!>     lightest free block (the usual static equilibrium criterion);
!>   - no interpenetration beyond OVTOL (0.5 x ROUND by default), measured
!>     independently of the contact list: the depth of every rounding
!>     circle of every block into the rounded outline of every other block
!>     (convex blocks; exact distance to straight parts and arcs).
!> Stiff viscous boundaries are not in the code yet (no case here).
program test_stability_rigid
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_total_area, geometry_live_blocks
   use contact_refresh, only: geometry_refresh
   use contact_kinematics, only: contact_geometry
   use testing, only: check, testing_finish
   use testing_session, only: new_session => session_new_quiet, run => session_lines, &
                              kinetic_energy => rigid_kinetic_energy
   use commands_session, only: session_t, session_init, session_execute_line
   implicit none

   character(len=16) :: round_arg, spacing_arg

   if (command_argument_count() >= 2) then
      ! issue 18: a box cut by two continuous crossing sets, one ctest per
      ! rounding (tests/CMakeLists.txt: ROUND 0.02 / 0.05 / 0.1 / 0.2)
      call get_command_argument(1, round_arg)
      call get_command_argument(2, spacing_arg)
      call crossing_sets(trim(round_arg), trim(spacing_arg))
   else
      call stiffness_contrast()
      call acute_wedges()
      call tiny_rounding()
      call many_small_blocks()
      call dilation_confined()
      call long_run()
   end if
   call testing_finish()

contains

   ! ------------------------------------------------------------------ cases

   !> A 10 m box cut by two continuous joint sets (60 degrees at spacing
   !> `spacing`, -30 degrees at 1.3 m, both from the origin), the outer ring
   !> of blocks fixed, gravity: the first model a user writes. Before issue
   !> 18, 5 of 7 such combinations stopped at cycle 0 with "Contact Overlap
   !> Too Great" (a blunt corner's rounding circle reached through its
   !> block's other edge). Checks: every contact of the freshly cut model
   !> has a gap >= -1e-9 of the mean block size (reference: a tightly fitted
   !> mosaic touches everywhere and overlaps nowhere), then `settle`.
   subroutine crossing_sets(round, spacing)
      character(len=*), intent(in) :: round, spacing
      type(session_t) :: s
      real(wp) :: gmin, size
      character(len=60) :: deck(12)
      call new_session(s)
      deck(1) = 'ROUND '//round
      deck(2) = 'BLOCK 0,0 0,10 10,10 10,0'
      deck(3) = 'JSET 60,0 100,0 0,0 '//spacing//',0 (0,0)'
      deck(4) = 'JSET -30,0 100,0 0,0 1.3,0 (0,0)'
      deck(5) = 'PROP MAT=1 DENS=2600'
      deck(6) = 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.6'
      deck(7) = 'FIX -1,11 -1,1'
      deck(8) = 'FIX -1,11 9,11'
      deck(9) = 'FIX -1,1 -1,11'
      deck(10) = 'FIX 9,11 -1,11'
      deck(11) = 'GRAVITY 0 -9.81'
      deck(12) = 'DAMP AUTO'
      call run(s, deck)
      call initial_gaps(s, gmin, size)
      write (*, '(a,es10.3,a,es10.3)') '  crossing sets ROUND '//round//' spacing '//spacing// &
         ': smallest initial gap ', gmin, ', mean block size ', size
      call check(gmin >= -1.0e-9_wp*size, 'crossing sets ROUND '//round//' spacing '// &
                 spacing//': no contact overlaps at cycle 0')
      call check(free_blocks(s) > 20, 'crossing sets: many free blocks')
      call settle(s, 'crossing sets ROUND '//round//' spacing '//spacing, 20000, 1000)
   end subroutine crossing_sets

   !> Smallest contact gap of the model as cut (contacts rebuilt) and the
   !> mean block size sqrt(area / blocks).
   subroutine initial_gaps(s, gmin, size)
      type(session_t), intent(inout) :: s
      real(wp), intent(out) :: gmin, size
      integer(ip) :: c
      real(wp) :: gap, nx, ny, px, py
      call geometry_refresh(s%model%geometry, force=.true.)
      gmin = huge(1.0_wp)
      associate (geo => s%model%geometry)
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            call contact_geometry(geo, c, 0.0_wp, gap, nx, ny, px, py)
            gmin = min(gmin, gap)
         end do
         size = sqrt(geometry_total_area(geo)/real(geometry_live_blocks(geo), wp))
      end associate
   end subroutine initial_gaps

   !> (a) 2 x 5 blocks of 1 m, bottom row fixed; the joint at y = 3 has
   !> JKN = JKS = 1e7 Pa/m, every other joint 1e11 (contrast 1e4), so the
   !> time step follows the stiff joints and the soft joint's mode is 100
   !> times slower (about 3000 steps per period).
   subroutine stiffness_contrast()
      type(session_t) :: s
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 0.05', 'BLOCK 0,0 0,5 2,5 2,0', &
                   'JSET 0,0 20,0 0,0 1,0 0,0', 'JSET 90,0 20,0 0,0 1,0 0,0', &
                   'PROP MAT=1 DENS=2500', &
                   'PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=0.5', &
                   'PROP JMAT=2 JKN=1E7 JKS=1E7 JFRIC=0.5', &
                   'CHANGE -1,3 2.97,3.03 JMAT=2', &
                   'FIX -1,3 0,1', 'GRAVITY 0 -10', 'DAMP AUTO'])
      call check(count(s%model%geometry%contacts%jmat(1:s%model%geometry%contacts%n) == 2 .and. &
                       s%model%geometry%contacts%live(1:s%model%geometry%contacts%n)) >= 4, &
                 'contrast: the soft joint has its own joint material')
      call settle(s, 'contrast', 60000, 1000)
   end subroutine stiffness_contrast

   !> (b) Acute blocks under gravity on a fixed base: a layer cut by two
   !> parallel joints at 7 degrees (two 7-degree triangles and a
   !> parallelogram with two 7-degree corners) and above it a layer cut
   !> corner to corner at 5 degrees. Friction 0.5 > tan 7 deg: all stick.
   subroutine acute_wedges()
      type(session_t) :: s
      real(wp) :: amin
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,2.875 10,2.875 10,0', &
                   'SPLIT -1,1 11,1', 'SPLIT -1,2 11,2', &
                   'SPLIT 0,1 8.14435,2', 'SPLIT 1.85565,1 10,2', 'SPLIT 0,2 10,2.875', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                   'FIX -1,11 0,1', 'GRAVITY 0 -10', 'DAMP AUTO'])
      amin = smallest_angle(s)
      call check(amin > 4.9_wp .and. amin < 7.1_wp, &
                 'wedges: the assembly has corners of 5 to 7 degrees')
      call check(free_blocks(s) == 5, 'wedges: five acute free blocks')
      call settle(s, 'wedges', 20000, 500)
   end subroutine acute_wedges

   !> (c) ROUND 1e-4 on a 1 m model: 5 x 5 blocks of 0.2 m, bottom row
   !> fixed (OVTOL 5e-5 m, contact margin 1e-4 m).
   subroutine tiny_rounding()
      type(session_t) :: s
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 1E-4', 'BLOCK 0,0 0,1 1,1 1,0', &
                   'JSET 0,0 10,0 0,0 0.2,0 0,0', 'JSET 90,0 10,0 0,0 0.2,0 0,0', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                   'FIX -1,2 0,0.2', 'GRAVITY 0 -10', 'DAMP AUTO'])
      call check(free_blocks(s) == 20, 'tiny rounding: 20 free blocks of 0.2 m')
      call settle(s, 'tiny rounding', 10000, 250)
   end subroutine tiny_rounding

   !> (d) A 10 m x 1 m block resting on ten 1 m blocks (two of them 0.5 m
   !> wide, so twelve) on a fixed base.
   subroutine many_small_blocks()
      type(session_t) :: s
      integer :: nb
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,3 10,3 10,0', &
                   'SPLIT -1,1 11,1', 'SPLIT -1,2 11,2', &
                   'SPLIT 0.5,1 0.5,2', 'SPLIT 1,1 1,2', 'SPLIT 2,1 2,2', 'SPLIT 3,1 3,2', &
                   'SPLIT 4,1 4,2', 'SPLIT 5,1 5,2', 'SPLIT 6,1 6,2', 'SPLIT 7,1 7,2', &
                   'SPLIT 8,1 8,2', 'SPLIT 9,1 9,2', 'SPLIT 9.5,1 9.5,2', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                   'FIX -1,11 0,1', 'GRAVITY 0 -10', 'DAMP AUTO'])
      call check(free_blocks(s) == 13, 'many: one long block on twelve small ones')
      call settle(s, 'many', 10000, 250)
      nb = loaded_neighbours(s, 5.0_wp, 2.5_wp)
      write (*, '(a,i0,a)') '  many: the long block carries ', nb, ' blocks'
      call check(nb >= 8, 'many: the long block bears on >= 8 smaller blocks at the end')
   end subroutine many_small_blocks

   !> (e) A 4 m x 1 m block between a fixed base and a fixed roof (zero
   !> gaps), pushed sideways by F = 5e4 N/m; friction 0.3, JDIL 0.1, a
   !> gravity of 0.01 (W = 100 N/m). Without dilation F > 0.3 W and it would
   !> slide for ever; sliding opens both joints against the fixed roof, the
   !> normal forces grow until friction holds. Reference (statics with both
   !> joints at the friction limit): N_roof = (F/mu - W)/2 = 8.328e4 N,
   !> tolerance 5 % (measured +0.9 %). The gravity is small so that the
   !> block's sag, W / (JKN L) = 2.5e-8 m, leaves the roof joint closed:
   !> under g = 10 it sagged 2.5e-5 m, the roof joint was open by that until
   !> the base's dilation closed it after 0.25 mm of unconfined sliding, and
   !> the block then came to rest above the limit statics (N_roof 3.95e4
   !> against 3.33e4). It matched them before only because the open roof
   !> joint made a normal force out of nothing from its shear (an open
   !> dilatant contact now carries nothing: verification.closed_forms).
   subroutine dilation_confined()
      type(session_t) :: s
      real(wp) :: nroof
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,3 10,3 10,0', &
                   'SPLIT -1,1 11,1', 'SPLIT -1,2 11,2', 'SPLIT 3,1 3,2', 'SPLIT 7,1 7,2', &
                   'DELETE 0,3 1,2', 'DELETE 7,10 1,2', &
                   'PROP MAT=1 DENS=2500', &
                   'PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC=0.3 JDIL=0.1', &
                   'FIX -1,11 0,1', 'FIX -1,11 2,3', 'LOAD 3,7 1,2 5E4 0', &
                   'GRAVITY 0 -0.01', 'DAMP AUTO'])
      call check(free_blocks(s) == 1, 'dilation: one confined free block')
      call settle(s, 'dilation', 20000, 500)
      nroof = normal_force_along(s, 2.0_wp)
      write (*, '(a,es12.5,a)') '  dilation: roof normal force ', nroof, ' N (statics 8.3283e4)'
      call check(abs(nroof - (5.0e4_wp/0.3_wp - 1.0e2_wp)/2.0_wp) <= 0.05_wp*(5.0e4_wp/0.3_wp - 1.0e2_wp)/2.0_wp, &
                 'dilation: roof force (F/mu - W)/2 within 5 %')
   end subroutine dilation_confined

   !> (f) 100 000 cycles of a three-block column on a fixed base. Besides the
   !> common checks: no creep once settled (motion of every block below
   !> 1e-9 m over the last 90 000 cycles) and the adaptive damping constant
   !> stays finite and positive.
   subroutine long_run()
      type(session_t) :: s
      real(wp), allocatable :: x0(:), y0(:)
      real(wp) :: creep, kepeak
      integer(ip) :: n
      call new_session(s)
      call run(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,4 1,4 1,0', &
                   'SPLIT -1,1 2,1', 'SPLIT -1,2 2,2', 'SPLIT -1,3 2,3', &
                   'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                   'FIX -1,2 0,1', 'GRAVITY 0 -10', 'DAMP AUTO'])
      call settle(s, 'long run (first 10 000)', 10000, 500, ke_peak=kepeak)
      n = s%model%geometry%blocks%n
      x0 = s%model%geometry%blocks%xc(1:n)
      y0 = s%model%geometry%blocks%yc(1:n)
      call settle(s, 'long run', 90000, 10000, ke_ref=kepeak)
      call check(s%model%mech%step == 100000, 'long run: 100 000 cycles done')
      creep = maxval(hypot(s%model%geometry%blocks%xc(1:n) - x0, s%model%geometry%blocks%yc(1:n) - y0), &
                     mask=s%model%geometry%blocks%live(1:n))
      write (*, '(a,es10.3,a)') '  long run: creep over the last 90 000 cycles ', creep, ' m'
      call check(creep < 1.0e-9_wp, 'long run: no creep once settled (< 1e-9 m)')
      call check(ieee_is_finite(s%model%mech%auto_alpha) .and. s%model%mech%auto_alpha > 0.0_wp, &
                 'long run: adaptive damping constant finite and positive')
   end subroutine long_run

   ! ---------------------------------------------------------------- helpers

   !> `ncycles` cycles in CYCLE commands of 25 steps for the first 500 (to
   !> see the peak of the motion), then of `chunk` steps, with the checks of
   !> the module header after every command. The decay is judged against
   !> the largest kinetic energy seen in this call, or `ke_ref` if given
   !> (a later stretch of a run that had settled before); `ke_peak`
   !> returns that largest value.
   subroutine settle(s, name, ncycles, chunk, ke_ref, ke_peak)
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer, intent(in) :: ncycles, chunk
      real(wp), intent(in), optional :: ke_ref
      real(wp), intent(out), optional :: ke_peak
      integer :: done, n
      real(wp) :: ke, kemax, work, ratio, wmin, pen, ovtol
      logical :: finite, bounded
      character(len=40) :: line
      ovtol = s%model%mech%ovtol
      if (ovtol <= 0.0_wp) ovtol = 0.5_wp*s%model%geometry%round
      kemax = 0.0_wp
      ratio = 0.0_wp
      pen = 0.0_wp
      ke = 0.0_wp
      work = 0.0_wp
      finite = .true.
      bounded = .true.
      done = 0
      do while (done < ncycles)
         n = chunk
         if (done < 500) n = 25
         n = min(n, ncycles - done)
         write (line, '(a,i0)') 'CYCLE ', n
         call run(s, [line])
         done = done + n
         if (s%nerrors > 0) exit
         finite = finite .and. all_finite(s)
         if (.not. finite) exit
         ke = kinetic_energy(s)
         work = external_work(s)
         kemax = max(kemax, ke)
         ratio = max(ratio, ke/max(work, tiny(1.0_wp)))
         if (ke > 1.05_wp*work) bounded = .false.
         pen = max(pen, max_penetration(s))
      end do
      if (present(ke_ref)) kemax = ke_ref
      if (present(ke_peak)) ke_peak = kemax
      wmin = lightest_weight(s)
      write (*, '(2x,a,a,i0,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a,es9.2)') name, ': step ', &
         s%model%mech%step, ', KE/peak ', ke/max(kemax, tiny(1.0_wp)), ', KE/work ', &
         ke/max(work, tiny(1.0_wp)), ', max KE/work ', ratio, ', unbalanced/weight ', &
         s%model%mech%unbalanced/wmin, ', penetration ', pen, ', OVTOL ', ovtol
      call check(s%nerrors == 0, name//': no error')
      call check(finite, name//': positions, velocities and contact forces finite')
      call check(bounded, name//': kinetic energy <= 1.05 x work of gravity and loads')
      call check(ke <= 1.0e-8_wp*kemax, name//': kinetic energy decayed below 1e-8 of its peak')
      call check(s%model%mech%unbalanced <= 1.0e-3_wp*wmin, &
                 name//': unbalanced force below 1e-3 of the lightest block weight')
      call check(pen <= ovtol, name//': no interpenetration beyond OVTOL at any check')
   end subroutine settle

   logical function all_finite(s) result(ok)
      type(session_t), intent(in) :: s
      integer(ip) :: nb, nc
      nb = s%model%geometry%blocks%n
      nc = s%model%geometry%contacts%n
      associate (bl => s%model%geometry%blocks, ct => s%model%geometry%contacts)
         ok = all(ieee_is_finite(bl%xc(1:nb)) .and. ieee_is_finite(bl%yc(1:nb)) .and. &
                  ieee_is_finite(bl%vx(1:nb)) .and. ieee_is_finite(bl%vy(1:nb)) .and. &
                  ieee_is_finite(bl%vr(1:nb)) .and. ieee_is_finite(bl%rot(1:nb)))
         ok = ok .and. all(ieee_is_finite(ct%state%fn(1:nc)) .and. ieee_is_finite(ct%state%fs(1:nc)))
         ok = ok .and. all(ieee_is_finite(s%model%geometry%corners%x(1:s%model%geometry%corners%n)))
         ok = ok .and. ieee_is_finite(s%model%mech%unbalanced) .and. ieee_is_finite(s%model%mech%dt)
      end associate
   end function all_finite

   !> Work of gravity and of the (constant) LOADs on the centroid
   !> displacements since the start.
   real(wp) function external_work(s) result(w)
      type(session_t), intent(in) :: s
      integer(ip) :: b
      w = 0.0_wp
      associate (bl => s%model%geometry%blocks, g => s%model%gravity)
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fixed(b)) cycle
            w = w + (bl%mass(b)*g(1) + bl%lx(b))*bl%ux(b) + (bl%mass(b)*g(2) + bl%ly(b))*bl%uy(b)
         end do
      end associate
   end function external_work

   real(wp) function lightest_weight(s) result(w)
      type(session_t), intent(in) :: s
      integer(ip) :: b
      w = huge(1.0_wp)
      associate (bl => s%model%geometry%blocks)
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fixed(b)) cycle
            w = min(w, bl%mass(b)*hypot(s%model%gravity(1), s%model%gravity(2)))
         end do
      end associate
   end function lightest_weight

   integer function free_blocks(s) result(n)
      type(session_t), intent(in) :: s
      integer(ip) :: nb
      nb = s%model%geometry%blocks%n
      n = count(s%model%geometry%blocks%live(1:nb) .and. .not. s%model%geometry%blocks%fixed(1:nb))
   end function free_blocks

   !> Smallest interior corner angle [degrees] of the live blocks.
   real(wp) function smallest_angle(s) result(amin)
      type(session_t), intent(in) :: s
      integer(ip) :: b, c, k, p, q
      real(wp) :: ux, uy, vx, vy
      amin = 180.0_wp
      associate (geo => s%model%geometry)
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            c = geo%blocks%first_corner(b)
            do k = 1, geo%blocks%ncorner(b)
               p = geo%corners%prev(c)
               q = geo%corners%next(c)
               ux = geo%corners%x(p) - geo%corners%x(c); uy = geo%corners%y(p) - geo%corners%y(c)
               vx = geo%corners%x(q) - geo%corners%x(c); vy = geo%corners%y(q) - geo%corners%y(c)
               amin = min(amin, abs(atan2(ux*vy - uy*vx, ux*vx + uy*vy))*45.0_wp/atan(1.0_wp))
               c = q
            end do
         end do
      end associate
   end function smallest_angle

   !> Number of distinct blocks pressing (fn > 0) on the block whose
   !> centroid is nearest (x, y).
   integer function loaded_neighbours(s, x, y) result(n)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: x, y
      integer(ip) :: b, c, other
      logical, allocatable :: seen(:)
      associate (geo => s%model%geometry)
         b = minloc(hypot(geo%blocks%xc(1:geo%blocks%n) - x, geo%blocks%yc(1:geo%blocks%n) - y), 1, &
                    mask=geo%blocks%live(1:geo%blocks%n))
         allocate (seen(geo%blocks%n))
         seen = .false.
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c) .or. geo%contacts%state%fn(c) <= 0.0_wp) cycle
            if (geo%contacts%block1(c) == b) then
               other = geo%contacts%block2(c)
            else if (geo%contacts%block2(c) == b) then
               other = geo%contacts%block1(c)
            else
               cycle
            end if
            seen(other) = .true.
         end do
         n = count(seen)
      end associate
   end function loaded_neighbours

   !> Sum of the normal forces of the live contacts lying on the horizontal
   !> line y = yline (within 0.1 m).
   real(wp) function normal_force_along(s, yline) result(f)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: yline
      integer(ip) :: c
      f = 0.0_wp
      associate (ct => s%model%geometry%contacts)
         do c = 1, ct%n
            if (ct%live(c) .and. abs(ct%y(c) - yline) < 0.1_wp) f = f + ct%state%fn(c)
         end do
      end associate
   end function normal_force_along

   !> Largest overlap of two rounded outlines (0 if none), independent of
   !> the contact list: for every corner arc of one block, its depth into
   !> every other nearby block. The circle of a corner reaches furthest
   !> into block X towards the nearest point Q of X; if that direction lies
   !> on the corner's arc (the cone between the outward normals of its two
   !> edges) the depth is r - d(C, X); otherwise the arc's deepest point is
   !> one of its ends (the tangent points on the edges). (Circles of obtuse
   !> corners of thin blocks reach out of their own block, so whole circles
   !> would not do.) Blocks are convex.
   real(wp) function max_penetration(s) result(pen)
      type(session_t), intent(in) :: s
      integer(ip) :: a, b, c, k
      real(wp) :: reach
      pen = 0.0_wp
      associate (geo => s%model%geometry)
         reach = 4.0_wp*geo%round
         do a = 1, geo%blocks%n
            if (.not. geo%blocks%live(a)) cycle
            do b = 1, geo%blocks%n
               if (b == a .or. .not. geo%blocks%live(b)) cycle
               if (.not. boxes_near(geo, a, b, reach)) cycle
               c = geo%blocks%first_corner(a)
               do k = 1, geo%blocks%ncorner(a)
                  pen = max(pen, arc_depth(geo, c, b))
                  c = geo%corners%next(c)
               end do
            end do
         end do
      end associate
   end function max_penetration

   logical function boxes_near(geo, a, b, reach)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: a, b
      real(wp), intent(in) :: reach
      real(wp) :: ax0, ax1, ay0, ay1, bx0, bx1, by0, by1
      call corner_box(geo, a, ax0, ax1, ay0, ay1)
      call corner_box(geo, b, bx0, bx1, by0, by1)
      boxes_near = ax0 <= bx1 + reach .and. bx0 <= ax1 + reach .and. &
                   ay0 <= by1 + reach .and. by0 <= ay1 + reach
   end function boxes_near

   subroutine corner_box(geo, b, x0, x1, y0, y1)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      real(wp), intent(out) :: x0, x1, y0, y1
      integer(ip) :: c, k
      x0 = huge(1.0_wp); x1 = -huge(1.0_wp); y0 = huge(1.0_wp); y1 = -huge(1.0_wp)
      c = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         x0 = min(x0, geo%corners%x(c)); x1 = max(x1, geo%corners%x(c))
         y0 = min(y0, geo%corners%y(c)); y1 = max(y1, geo%corners%y(c))
         c = geo%corners%next(c)
      end do
   end subroutine corner_box

   !> Depth of the arc of corner c into block x (see max_penetration).
   real(wp) function arc_depth(geo, c, x) result(depth)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c, x
      real(wp) :: cx, cy, r, d, qx, qy, t1x, t1y, t2x, t2y
      cx = geo%corners%rx(c)
      cy = geo%corners%ry(c)
      r = geo%corners%radius(c)
      d = signed_distance(geo, cx, cy, x, qx, qy)
      depth = 0.0_wp
      if (d >= r) return
      if (d <= 0.0_wp) then
         depth = r - d
      else if (in_cone(geo, c, orientation(geo, geo%corners%block(c)), qx - cx, qy - cy)) then
         depth = r - d
      else
         call foot(geo, cx, cy, geo%corners%prev(c), c, t1x, t1y)
         call foot(geo, cx, cy, c, geo%corners%next(c), t2x, t2y)
         depth = max(0.0_wp, -signed_distance(geo, t1x, t1y, x, qx, qy), &
                     -signed_distance(geo, t2x, t2y, x, qx, qy))
      end if
   end function arc_depth

   !> Foot (fx, fy) of point (px, py) on the line of the edge from corner p
   !> to corner q.
   subroutine foot(geo, px, py, p, q, fx, fy)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: p, q
      real(wp), intent(out) :: fx, fy
      real(wp) :: vx, vy, l, e
      vx = geo%corners%x(q) - geo%corners%x(p)
      vy = geo%corners%y(q) - geo%corners%y(p)
      l = hypot(vx, vy)
      vx = vx/l
      vy = vy/l
      e = (px - geo%corners%x(p))*vx + (py - geo%corners%y(p))*vy
      fx = geo%corners%x(p) + e*vx
      fy = geo%corners%y(p) + e*vy
   end subroutine foot

   !> +1 for a clockwise corner ring (outward normal left of each edge), -1
   !> for counter-clockwise.
   real(wp) function orientation(geo, b) result(o)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      integer(ip) :: c, q, k
      real(wp) :: area2
      area2 = 0.0_wp
      c = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         q = geo%corners%next(c)
         area2 = area2 + geo%corners%x(c)*geo%corners%y(q) - geo%corners%x(q)*geo%corners%y(c)
         c = q
      end do
      o = merge(1.0_wp, -1.0_wp, area2 < 0.0_wp)
   end function orientation

   !> Outward unit normal of the edge from corner p to corner q.
   subroutine edge_normal(geo, p, q, o, nx, ny)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: p, q
      real(wp), intent(in) :: o
      real(wp), intent(out) :: nx, ny
      real(wp) :: ux, uy, l
      ux = geo%corners%x(q) - geo%corners%x(p)
      uy = geo%corners%y(q) - geo%corners%y(p)
      l = hypot(ux, uy)
      nx = -o*uy/l
      ny = o*ux/l
   end subroutine edge_normal

   !> Whether direction (wx, wy) lies in the cone between the outward
   !> normals of the two edges at (convex) corner c.
   logical function in_cone(geo, c, o, wx, wy)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: o, wx, wy
      real(wp) :: ax, ay, bx, by, turn
      call edge_normal(geo, geo%corners%prev(c), c, o, ax, ay)
      call edge_normal(geo, c, geo%corners%next(c), o, bx, by)
      turn = ax*by - ay*bx
      in_cone = (ax*wy - ay*wx > 0.0_wp .eqv. turn > 0.0_wp) .and. &
                (wx*by - wy*bx > 0.0_wp .eqv. turn > 0.0_wp)
   end function in_cone

   !> Signed distance (positive outside) from (px, py) to the rounded
   !> outline of convex block b, and the nearest outline point (qx, qy):
   !> straight parts run between the feet of the corner-circle centres on
   !> each edge; arcs (in the cone of their corner) join them.
   real(wp) function signed_distance(geo, px, py, b, qx, qy) result(d)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: b
      real(wp), intent(out) :: qx, qy
      integer(ip) :: c, q, k
      real(wp) :: o, ux, uy, l, nx, ny, s0, s1, t, dist, wx, wy, r, h
      logical :: inside, clipped
      associate (co => geo%corners)
         o = orientation(geo, b)
         dist = huge(1.0_wp)
         qx = px
         qy = py
         inside = .true.
         clipped = .false.
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            q = co%next(c)
            ux = co%x(q) - co%x(c)
            uy = co%y(q) - co%y(c)
            l = hypot(ux, uy)
            ux = ux/l
            uy = uy/l
            nx = -o*uy
            ny = o*ux
            if ((px - co%x(c))*nx + (py - co%y(c))*ny > 0.0_wp) inside = .false.
            ! straight part between the feet of the two circle centres
            s0 = (co%rx(c) - co%x(c))*ux + (co%ry(c) - co%y(c))*uy
            s1 = (co%rx(q) - co%x(c))*ux + (co%ry(q) - co%y(c))*uy
            t = min(max((px - co%x(c))*ux + (py - co%y(c))*uy, s0), s1)
            h = hypot(px - co%x(c) - t*ux, py - co%y(c) - t*uy)
            if (h < dist) then
               dist = h
               qx = co%x(c) + t*ux
               qy = co%y(c) + t*uy
            end if
            ! arc of corner c
            r = co%radius(c)
            wx = px - co%rx(c)
            wy = py - co%ry(c)
            h = hypot(wx, wy)
            if (h > 0.0_wp) then
               if (in_cone(geo, c, o, wx, wy)) then
                  if (abs(h - r) < dist) then
                     dist = abs(h - r)
                     qx = co%rx(c) + r*wx/h
                     qy = co%ry(c) + r*wy/h
                  end if
                  if (h > r) clipped = .true.
               end if
            end if
            c = q
         end do
      end associate
      inside = inside .and. .not. clipped
      d = merge(-dist, dist, inside)
   end function signed_distance

end program test_stability_rigid
