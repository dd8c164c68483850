!> Hard scenes users build (label `stability`, issue 18), each run to a
!> physical answer with the reference and tolerance stated per case:
!>   1. a 5-degree wedge in a notch of the same angle (frictionless): each
!>      face carries W / (2 sin 2.5 deg) = 11.46 W, the vertical components
!>      add up to W (statics; 1e-4), overlaps below OVTOL;
!>   2. eight wedges meeting at one corner (a square cut by four lines
!>      through its centre) in a frictionless fixed box under gravity: the
!>      base carries the weight of all eight, the horizontal line through
!>      the corner the weight of the upper four (statics; 1e-4), the
!>      unbalanced force decays;
!>   3. two zoned blocks in series with Young's moduli 1e4 apart, squeezed
!>      by a prescribed top displacement: the top reaction is the series
!>      spring u / (h1/M1 + h2/M2 + 1/kn) (1e-3);
!>   4. a joint 1e3 times stiffer than the zones beside it (JKN = 1e3
!>      M / zone size): the time step follows the joint, and the reaction
!>      is again the series spring (1e-3);
!>   5. a zoned block on a frictional joint, its top driven back and forth
!>      20 times: the joint slides at |F_s| = mu F_n with F_n = W (1e-3),
!>      the slip per half cycle is the travel minus the elastic part
!>      (Coulomb, 2 %), and no ratcheting: the slip at every positive peak
!>      equals the first (1 % of a half cycle's slip).
!> Geometry by BLOCK, SPLIT and DELETE only (straight cuts through a
!> common point; no cut close to a corner).
program test_stability_scenes
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use testing, only: check, testing_finish
   use testing_session, only: new_session => session_new_quiet, run => session_lines, &
                              kinetic => rigid_kinetic_energy, held_top_mean, held_top_fy
   use commands_session, only: session_t, session_init, session_execute_line
   implicit none

   real(wp), parameter :: pi = acos(-1.0_wp)

   call wedge_in_notch()
   call eight_at_a_corner()
   call series_contrast('contrast 1e4', 'PROP MAT=2 DENS=2000 K=1E12 G=6E11', 'JKN=1E14 JKS=1E14', &
                        1.0e12_wp + 8.0e11_wp, 1.0e14_wp)
   call series_contrast('stiff joint 1e3', 'PROP MAT=2 DENS=2000 K=1E8 G=6E7', 'JKN=7.2E11 JKS=7.2E11', &
                        1.0e8_wp + 8.0e7_wp, 7.2e11_wp)
   call cycled_slip()
   call testing_finish()

contains

   !> A wedge with a 5-degree tip, cut out of a 2 x 3 block by two SPLITs
   !> through (1, 0.5) at +-2.5 deg from the vertical; the piece below the
   !> tip is deleted, the two sides fixed. Frictionless faces, so each
   !> face's normal force N satisfies 2 N sin(2.5 deg) = W.
   subroutine wedge_in_notch()
      type(session_t) :: s
      character(len=100) :: cut1, cut2
      real(wp) :: t, w, fx, fy, nleft, nright, ovl
      integer(ip) :: b
      t = tan(2.5_wp*pi/180.0_wp)
      write (cut1, '(a,f11.8,a,f11.8,a)') 'SPLIT ', 1.0_wp + 1.5_wp*t, ',-1 ', 1.0_wp - 3.5_wp*t, ',4'
      write (cut2, '(a,f11.8,a,f11.8,a)') 'SPLIT ', 1.0_wp - 1.5_wp*t, ',-1 ', 1.0_wp + 3.5_wp*t, ',4'
      call new_session(s)
      call run(s, [character(len=100) :: 'ROUND 0.01', 'BLOCK 0,0 0,3 2,3 2,0', cut1, cut2, &
                   'DELETE 0.9 1.1 0 0.45', 'PROP MAT=1 DENS=2500', &
                   'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0', 'FIX 0 0.8 0 3', 'FIX 1.2 2 0 3', &
                   'GRAVITY 0 -10', 'DAMP AUTO', 'CYCLE 30000'])
      b = block_near(s, 1.0_wp, 2.17_wp)
      w = s%model%geometry%blocks%area(b)*2500.0_wp*10.0_wp
      call contact_force_on(s, b, fx, fy)
      nleft = normal_force_between(s, b, block_near(s, 0.48_wp, 1.47_wp))
      nright = normal_force_between(s, b, block_near(s, 1.52_wp, 1.47_wp))
      ovl = max_overlap(s)
      write (*, '(a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es9.2)') '  wedge: W ', w, ', contacts up ', fy, &
         ', faces ', nleft, ' / ', nright, ' N, overlap ', ovl
      call check(s%nerrors == 0, 'wedge: no error (no overlap error)')
      call check(abs(s%model%geometry%blocks%area(b) - 6.25_wp*t) < 1.0e-6_wp, 'wedge: the 5-degree wedge is one block')
      call check(abs(fy/w - 1.0_wp) < 1.0e-4_wp .and. abs(fx) < 1.0e-4_wp*w, &
                 'wedge: contact forces carry its weight (1e-4)')
      call check(abs(nleft/(w/(2.0_wp*sin(2.5_wp*pi/180.0_wp))) - 1.0_wp) < 1.0e-4_wp .and. &
                 abs(nright/nleft - 1.0_wp) < 1.0e-4_wp, 'wedge: each face N = W / (2 sin 2.5 deg) (1e-4)')
      call check(ovl < 0.5_wp*s%model%geometry%round, 'wedge: overlaps below OVTOL')
      call check(s%model%mech%unbalanced < 1.0e-6_wp*w, 'wedge: static (unbalanced < 1e-6 W)')
   end subroutine wedge_in_notch

   !> A 2 x 2 square (x 1..3, y 1..3) between two fixed walls on a fixed
   !> base, cut into eight 45-degree wedges by four SPLITs through (2, 2).
   !> Frictionless walls (JMAT 2) take no vertical load, so the base
   !> carries all eight wedges (4 rho g) and the lower four carry the
   !> upper four (statics of the upper half). Friction 0.5 between the
   !> wedges: with every joint frictionless the assembly kept creeping at
   !> 5e-7 m/s (a zero-stiffness mode that DAMP AUTO, proportional to the
   !> unbalanced force, does not damp), though in force equilibrium.
   subroutine eight_at_a_corner()
      type(session_t) :: s
      real(wp) :: w, base, mid, wedge, ke0, kemax
      integer(ip) :: c, n8, bbase, b1, b2
      integer :: k
      call new_session(s)
      call run(s, [character(len=100) :: 'ROUND 0.005', 'BLOCK 0,0 0,3 4,3 4,0', 'SPLIT -1,1 5,1', &
                   'SPLIT 1,1 1,4', 'SPLIT 3,1 3,4', 'SPLIT 1,2 3,2', 'SPLIT 2,1 2,3', 'SPLIT 1,1 3,3', &
                   'SPLIT 1,3 3,1', 'PROP MAT=1 DENS=2500', 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                   'PROP JMAT=2 JKN=1E10 JKS=1E10 JFRIC=0', 'CHANGE 0.97 1.03 0.9 3.1 JMAT=2', &
                   'CHANGE 2.97 3.03 0.9 3.1 JMAT=2', &
                   'FIX -1 5 -1 1', 'FIX -1 1 -1 4', 'FIX 3 5 -1 4', 'GRAVITY 0 -10', 'DAMP AUTO'])
      ! contacts at the common corner: those within 2 ROUND of (2, 2)
      n8 = 0
      associate (ct => s%model%geometry%contacts)
         do c = 1, ct%n
            if (ct%live(c) .and. hypot(ct%x(c) - 2.0_wp, ct%y(c) - 2.0_wp) < 0.05_wp) n8 = n8 + 1
         end do
      end associate
      write (*, '(a,i0)') '  eight: contacts at the common corner ', n8
      call check(free_count(s) == 8, 'eight: eight free wedges')
      call check(n8 >= 8, 'eight: at least eight contacts at the common corner')
      ! the settling under gravity takes a few hundred steps: sampled finely
      kemax = 0.0_wp
      do k = 1, 59
         if (k <= 20) then
            call run(s, ['CYCLE 25'])
         else
            call run(s, ['CYCLE 500'])
         end if
         kemax = max(kemax, kinetic(s))
      end do
      ke0 = kinetic(s)
      w = 4.0_wp*2500.0_wp*10.0_wp
      wedge = w/8.0_wp
      base = 0.0_wp
      mid = 0.0_wp
      bbase = block_near(s, 2.0_wp, 0.5_wp)
      associate (ct => s%model%geometry%contacts, bl => s%model%geometry%blocks)
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            b1 = ct%block1(c)
            b2 = ct%block2(c)
            ! on the wedges from the base
            if (b1 == bbase .and. .not. bl%fixed(b2)) base = base + up_force(s, c, b2)
            if (b2 == bbase .and. .not. bl%fixed(b1)) base = base + up_force(s, c, b1)
            ! on the upper four wedges from the lower four
            if (bl%fixed(b1) .or. bl%fixed(b2)) cycle
            if ((bl%yc(b1) > 2.0_wp) .eqv. (bl%yc(b2) > 2.0_wp)) cycle
            mid = mid + up_force(s, c, upper(s, c))
         end do
      end associate
      write (*, '(a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es9.2,a,es9.2)') '  eight: base ', base, ' (', w, &
         '), line y = 2 ', mid, ' (', 0.5_wp*w, '), KE/peak ', ke0/max(kemax, tiny(1.0_wp)), &
         ', unbalanced/wedge ', s%model%mech%unbalanced/wedge
      call check(s%nerrors == 0 .and. all_blocks_finite(s), 'eight: no error, finite')
      call check(abs(base/w - 1.0_wp) < 1.0e-4_wp, 'eight: base carries the eight wedges (1e-4)')
      call check(abs(mid/(0.5_wp*w) - 1.0_wp) < 1.0e-4_wp, &
                 'eight: the line through the corner carries the upper four (1e-4)')
      call check(ke0 < 1.0e-8_wp*kemax .and. s%model%mech%unbalanced < 1.0e-6_wp*wedge, &
                 'eight: motion decayed (KE < 1e-8 peak, unbalanced < 1e-6 wedge weight)')
   end subroutine eight_at_a_corner

   !> Two zoned blocks, 1 m wide, h = 1 m each (bottom MAT 1: K = 1e8, G =
   !> 6e7; top MAT 2 as given), QUAD 0.25, rollers on the sides, base held,
   !> the top moved down 1e-5 m (YVEL for a measured number of steps, then
   !> held). Uniaxial strain: M = K + 4G/3; the top reaction per metre is
   !> u / (1/M1 + 1/M2 + 1/kn) (no gravity), within 1e-3.
   subroutine series_contrast(name, mat2, joint, m2, kn)
      character(len=*), intent(in) :: name, mat2, joint
      real(wp), intent(in) :: m2, kn
      type(session_t) :: s
      real(wp) :: m1, u, f, ref, dt1, dtz
      integer :: n
      character(len=40) :: line
      m1 = 1.0e8_wp + 8.0e7_wp
      call new_session(s)
      call run(s, [character(len=100) :: 'ROUND 0.01', 'BLOCK 0,0 0,2 1,2 1,0', 'SPLIT -1,1 2,1', &
                   'GEN QUAD 0.25', 'CHANGE 0 1 1 2 MAT=2', 'PROP MAT=1 DENS=2000 K=1E8 G=6E7', mat2, &
                   'PROP JMAT=1 '//joint//' JFRIC=1 JCOH=1E10 JTENS=1E10', &
                   'BOUND -0.1 0.1 -0.1 2.1 XVEL 0', 'BOUND 0.9 1.1 -0.1 2.1 XVEL 0', &
                   'BOUND -0.1 1.1 -0.1 0.1 YVEL 0', 'BOUND -0.1 1.1 1.9 2.1 YVEL -1E-3', 'DAMP AUTO', &
                   'CYCLE 1'])
      dt1 = s%model%mech%dt
      ! the zones alone would allow: the smallest zone step of MAT 2 / MAT 1
      dtz = 0.25_wp/sqrt(max(m1, m2)/2000.0_wp)
      n = max(1, nint(1.0e-5_wp/(1.0e-3_wp*dt1))) - 1
      write (line, '(a,i0)') 'CYCLE ', n
      call run(s, [character(len=100) :: line, 'BOUND -0.1 1.1 1.9 2.1 YVEL 0'])
      call settle_zones(s, 200000)
      u = -top_uy(s)
      f = top_reaction(s)
      ref = u/(1.0_wp/m1 + 1.0_wp/m2 + 1.0_wp/kn)
      write (*, '(2x,a,a,es11.4,a,es11.4,a,es11.4,a,es9.2,a,es10.3,a,es10.3)') name, ': u ', u, &
         ', reaction ', f, ' (series ', ref, ', rel. error ', f/ref - 1.0_wp, '), dt ', dt1, &
         ', zone wave step ', dtz
      call check(s%nerrors == 0 .and. all(ieee_is_finite(s%model%geometry%gridpoints%y(1:s%model%geometry%gridpoints%n))), &
                 name//': no error, finite')
      call check(abs(f/ref - 1.0_wp) < 1.0e-3_wp, name//': reaction = series spring (1e-3)')
      if (kn < 1.0e13_wp) call check(dt1 < 0.2_wp*dtz, name//': the time step follows the stiff joint')
   end subroutine series_contrast

   !> A 2 m x 0.5 m zoned block (QUAD 0.5; K = 1.6667e10, G = 1e10) on a
   !> fixed rigid base 3 m wide (the block's ends on the base's edge), joint
   !> JKN = JKS = 1e9 Pa/m, JFRIC = 0.5, gravity: N = W = 2.5e4 N/m. Its
   !> top gridpoints move at XVEL = +-2e-3 m/s, A = 1e-4 m out and back 20
   !> times (0 -> A -> -A ... -> A -> 0); at 1e-2 m/s the block's rocking
   !> put 2 % of dynamic load on the joint. Checks at every peak: the
   !> joint slides by Coulomb's law, |F_s| = mu sum F_n, and sum F_n = W
   !> (1e-3). At each reversal the shear force goes from +mu W to -mu W;
   !> the elastic travel of the top is 2 mu W c with the compliance
   !>   c = 1/(ks L) + h/(G L) + 12 h^2/(kn L^3)
   !> (joint shear, the block in simple shear, the block rocking on the
   !> joint under the couple F h), so the joint slips 2A - 2 mu W c per
   !> half cycle (2 %). Slip = mean x displacement of the block's bottom
   !> gridpoints minus the joint's elastic shear F_s/(ks L). No ratcheting:
   !> the slip at every positive peak equals the first (1 % of a half
   !> cycle's slip).
   subroutine cycled_slip()
      type(session_t) :: s
      real(wp) :: dt1, amp, w, mu, slip_half, ref, drift, comp, worst_coulomb, worst_fn
      real(wp) :: peaks(20), troughs(20)
      real(wp), parameter :: ks = 1.0e9_wp, kn = 1.0e9_wp, g_mod = 1.0e10_wp, h = 0.5_wp, l = 2.0_wp
      integer :: n, k
      integer(ip) :: bz, bb
      character(len=40) :: half, quarter
      call new_session(s)
      call run(s, [character(len=100) :: 'ROUND 0.01', 'BLOCK 0,0 0,1 3,1 3,0', 'SPLIT -1,0.5 4,0.5', &
                   'SPLIT 0.5,0.5 0.5,1.5', 'SPLIT 2.5,0.5 2.5,1.5', 'DELETE 0 0.5 0.5 1', &
                   'DELETE 2.5 3 0.5 1', &
                   'GEN 0.5 2.5 0.5 1 QUAD 0.5', 'PROP MAT=1 DENS=2500 K=1.6667E10 G=1E10', &
                   'PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC=0.5', 'FIX -1 4 0 0.5', 'GRAVITY 0 -10', &
                   'DAMP AUTO', 'CYCLE 20000'])
      bz = block_near(s, 1.5_wp, 0.75_wp)
      bb = block_near(s, 1.5_wp, 0.25_wp)
      dt1 = s%model%mech%dt
      n = max(10, nint(1.0e-4_wp/(2.0e-3_wp*dt1)))
      write (quarter, '(a,i0)') 'CYCLE ', n
      write (half, '(a,i0)') 'CYCLE ', 2*n
      w = 2.0_wp*0.5_wp*2500.0_wp*10.0_wp
      mu = 0.5_wp
      worst_coulomb = 0.0_wp
      worst_fn = 0.0_wp
      call run(s, [character(len=100) :: 'BOUND 0.4 2.6 0.9 1.1 XVEL 2E-3', quarter])
      amp = mean_ux_at(s, 1.0_wp)
      do k = 1, 20
         call slip_sample(s, bz, bb, mu, w, ks*l, peaks(k), worst_coulomb, worst_fn)
         call run(s, [character(len=100) :: 'BOUND 0.4 2.6 0.9 1.1 XVEL -2E-3', half])
         call slip_sample(s, bz, bb, mu, w, ks*l, troughs(k), worst_coulomb, worst_fn)
         if (k < 20) call run(s, [character(len=100) :: 'BOUND 0.4 2.6 0.9 1.1 XVEL 2E-3', half])
      end do
      call run(s, [character(len=100) :: 'BOUND 0.4 2.6 0.9 1.1 XVEL 2E-3', quarter, &
                   'BOUND 0.4 2.6 0.9 1.1 XVEL 0', 'CYCLE 2000'])
      comp = 1.0_wp/(ks*l) + h/(g_mod*l) + 12.0_wp*h*h/(kn*l**3)
      ref = 2.0_wp*amp - 2.0_wp*mu*w*comp
      slip_half = sum(peaks(2:20) - troughs(1:19))/19.0_wp
      drift = maxval(abs(peaks(2:20) - peaks(1)))
      write (*, '(a,es10.3,a,es9.2,a,es9.2,a,es11.4,a,es11.4,a,es10.3)') '  slip: A ', amp, &
         ', worst |Fs|/(mu Fn) - 1 ', worst_coulomb, ', worst Fn/W - 1 ', worst_fn, &
         ', slip per half cycle ', slip_half, ' (closed form ', ref, '), largest peak drift ', drift
      call check(s%nerrors == 0, 'slip: 20 cycles without error')
      call check(worst_coulomb < 1.0e-3_wp .and. worst_fn < 1.0e-3_wp, &
                 'slip: at every peak |Fs| = mu Fn and Fn = W (1e-3)')
      call check(abs(slip_half/ref - 1.0_wp) < 2.0e-2_wp, 'slip: slip per half cycle = Coulomb closed form (2 %)')
      call check(drift < 1.0e-2_wp*ref, 'slip: no ratcheting (every peak within 1 % of a half cycle of the first)')
      call check(peaks(1) > 0.0_wp .and. all(troughs < 0.0_wp), 'slip: the block slips both ways')
   end subroutine cycled_slip

   ! ---------------------------------------------------------------- helpers

   !> Joint slip of zoned block bz on base bb now (mean x displacement of
   !> its bottom gridpoints minus the joint's elastic shear F_s / (ks L)),
   !> and the worst deviations from |F_s| = mu F_n and F_n = W so far.
   subroutine slip_sample(s, bz, bb, mu, w, ksl, slip, worst_coulomb, worst_fn)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: bz, bb
      real(wp), intent(in) :: mu, w, ksl
      real(wp), intent(out) :: slip
      real(wp), intent(inout) :: worst_coulomb, worst_fn
      real(wp) :: fs, fy, fn
      call contact_force_on(s, bz, fs, fy)
      fn = normal_force_between(s, bz, bb)
      worst_coulomb = max(worst_coulomb, abs(abs(fs)/(mu*fn) - 1.0_wp))
      worst_fn = max(worst_fn, abs(fn/w - 1.0_wp))
      ! the contact force on the block opposes its slip
      slip = mean_ux_at(s, 0.5_wp) + fs/ksl
   end subroutine slip_sample

   !> CYCLE in chunks of 1000 until the unbalanced force is below 1e-7 of
   !> the largest gridpoint reaction (or `most` steps).
   subroutine settle_zones(s, most)
      type(session_t), intent(inout) :: s
      integer, intent(in) :: most
      integer :: done
      done = 0
      do while (done < most)
         call run(s, ['CYCLE 1000'])
         done = done + 1000
         if (s%nerrors > 0) exit
         if (s%model%mech%unbalanced < 1.0e-7_wp*abs(top_reaction(s))) exit
      end do
   end subroutine settle_zones

   integer(ip) function block_near(s, x, y) result(b)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: x, y
      associate (bl => s%model%geometry%blocks)
         b = minloc(hypot(bl%xc(1:bl%n) - x, bl%yc(1:bl%n) - y), 1, mask=bl%live(1:bl%n))
      end associate
   end function block_near

   integer function free_count(s) result(n)
      type(session_t), intent(in) :: s
      associate (bl => s%model%geometry%blocks)
         n = count(bl%live(1:bl%n) .and. .not. bl%fixed(1:bl%n))
      end associate
   end function free_count

   !> Force of contact c on block b (force on block2 = fn n - fs t).
   subroutine force_of(s, c, b, fx, fy)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: c, b
      real(wp), intent(out) :: fx, fy
      associate (ct => s%model%geometry%contacts)
         fx = ct%state%fn(c)*ct%nx(c) + ct%state%fs(c)*ct%ny(c)
         fy = ct%state%fn(c)*ct%ny(c) - ct%state%fs(c)*ct%nx(c)
         if (ct%block1(c) == b) then
            fx = -fx
            fy = -fy
         end if
      end associate
   end subroutine force_of

   subroutine contact_force_on(s, b, fx, fy)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: b
      real(wp), intent(out) :: fx, fy
      integer(ip) :: c
      real(wp) :: gx, gy
      fx = 0.0_wp
      fy = 0.0_wp
      associate (ct => s%model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            if (ct%block1(c) /= b .and. ct%block2(c) /= b) cycle
            call force_of(s, c, b, gx, gy)
            fx = fx + gx
            fy = fy + gy
         end do
      end associate
   end subroutine contact_force_on

   real(wp) function normal_force_between(s, a, b) result(f)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: a, b
      integer(ip) :: c
      f = 0.0_wp
      associate (ct => s%model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            if ((ct%block1(c) == a .and. ct%block2(c) == b) .or. (ct%block1(c) == b .and. ct%block2(c) == a)) &
               f = f + ct%state%fn(c)
         end do
      end associate
   end function normal_force_between

   !> The block of contact c whose centroid is higher.
   integer(ip) function upper(s, c) result(b)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: c
      associate (ct => s%model%geometry%contacts, bl => s%model%geometry%blocks)
         b = ct%block1(c)
         if (bl%yc(ct%block2(c)) > bl%yc(b)) b = ct%block2(c)
      end associate
   end function upper

   real(wp) function up_force(s, c, b) result(fy)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: c, b
      real(wp) :: fx
      call force_of(s, c, b, fx, fy)
   end function up_force

   !> Largest overlap of a live contact (minus its gap).
   real(wp) function max_overlap(s) result(o)
      type(session_t), intent(in) :: s
      integer(ip) :: c
      o = 0.0_wp
      associate (ct => s%model%geometry%contacts)
         do c = 1, ct%n
            if (ct%live(c)) o = max(o, -ct%gap(c))
         end do
      end associate
   end function max_overlap

   logical function all_blocks_finite(s) result(ok)
      type(session_t), intent(in) :: s
      associate (bl => s%model%geometry%blocks)
         ok = all(ieee_is_finite(bl%xc(1:bl%n)) .and. ieee_is_finite(bl%yc(1:bl%n)) .and. &
                  ieee_is_finite(bl%vx(1:bl%n)) .and. ieee_is_finite(bl%vy(1:bl%n)))
      end associate
   end function all_blocks_finite

   !> Gridpoints held in y above y = 1.5 (the loaded top).
   !> Mean y displacement of the held top (above 1.5 as generated).
   real(wp) function top_uy(s) result(u)
      type(session_t), intent(in) :: s
      u = held_top_mean(s, s%model%geometry%gridpoints%uy(1:s%model%geometry%gridpoints%n), 1.5_wp)
   end function top_uy

   !> The held top's reaction (sum of its y forces).
   real(wp) function top_reaction(s) result(f)
      type(session_t), intent(in) :: s
      f = held_top_fy(s, 1.5_wp)
   end function top_reaction

   !> Mean x displacement of the gridpoints at height y (within 0.01): the
   !> zoned block's bottom (y = 0.5, the joint slip: the base does not move)
   !> or its top (y = 1).
   real(wp) function mean_ux_at(s, y) result(u)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: y
      integer(ip) :: g, k
      u = 0.0_wp
      k = 0
      associate (gp => s%model%geometry%gridpoints)
         do g = 1, gp%n
            if (.not. gp%live(g) .or. abs(gp%y(g) - y) > 0.01_wp) cycle
            u = u + gp%ux(g)
            k = k + 1
         end do
      end associate
      u = u/max(k, 1)
   end function mean_ux_at

end program test_stability_scenes
