!> The time step of a simply-deformable block on a joint against the exact
!> critical step of that system (UDEC manual (ICG1.5, 1989), Section 3.2,
!> p. 3-2: the SDEF block's three strain modes; Section 4.5 FRACTION; the
!> central-difference limit dt_crit = 2 / omega_max, Section 3.5).
!> A 1 m square SDEF block (CONS 1, K 30 GPa, G 18 GPa, density 2600) rests
!> on a FIXed base; its joint (JKN, JKS = JKN / 10) is two corner contacts.
!> The exact system: the block's six modes (u, v, theta, exx, eyy, exy) with
!> M = diag(m, m, I, rho Ixx, rho Iyy, rho (Ixx + Iyy)) (a square: Ixy = 0),
!> the internal stiffness A [[D11, D12, 0], [D12, D11, 0], [0, 0, 4G]] on
!> the strains and at each contact (read from the model: point, normal,
!> length) kn = JKN l along the normal and ks = JKS l along the joint;
!> omega_max^2 the largest root of det(K - lambda M) = 0, found here by
!> bisection on the count of negative pivots of K - lambda M (Sylvester),
!> independent of the engine's Jacobi rotations.
!> Checks, for JKN 2e11 and 2e10 Pa/m:
!> * dt <= dt_crit: a longer step is unstable (the model is linear; no
!>   tolerance);
!> * dt >= 0.2 dt_crit (JKN 2e11) and >= 0.3 dt_crit (JKN 2e10): the bound
!>   is half the critical step of the block held by the stiffest joint at
!>   every corner in x and y, which this block does not have (measured
!>   0.25 and 0.41). Before the combined bound the corner contacts took
!>   FRACTION 0.1 on the corner's mass: 0.10 and 0.25 of dt_crit, and these
!>   checks failed (5 - 10 times below the critical step).
program test_sdef_timestep
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run
   use testing, only: check, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call case(2.0e11_wp, 0.2_wp)
   call case(2.0e10_wp, 0.3_wp)
   call testing_finish()

contains

   subroutine case(jkn, lower)
      real(wp), intent(in) :: jkn, lower
      type(error_t), allocatable :: error
      character(len=40) :: tag
      real(wp), parameter :: rho = 2600.0_wp, kb = 30.0e9_wp, gb = 18.0e9_wp
      real(wp) :: kmat(6, 6), mass(6), q(6), d11, d12, rx, ry, tx, ty, l, lsum, dt, crit
      integer(ip) :: b, c, top
      integer :: ncontact
      write (tag, '(a,es8.1)') 'JKN ', jkn
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.001')
      call run('BLOCK 0,0 0,2 3,2 3,0')
      call run('CRACK 0,1 3,1')
      call run('CRACK 1,1 1,2')
      call run('CRACK 2,1 2,2')
      call run('DELETE 0 1 1 2')
      call run('DELETE 2 3 1 2')
      call run('PROP MAT 1 DENS 2600 K 30e9 G 18e9')
      write (tag, '(es10.3,a,es10.3)') jkn, ' JKS ', 0.1_wp*jkn
      call run('PROP JMAT 1 JKN '//trim(adjustl(tag(1:10)))//' JKS '//trim(adjustl(tag(16:)))// &
               ' JFRIC 0.7 JCOH 0 JTENS 0')
      write (tag, '(a,es8.1)') 'JKN ', jkn
      call run('CHANGE 1 2 1 2 SDEF')
      call run('CHANGE 1 2 1 2 CONS 1')
      call run('FIX 0 3 0 1')
      call run('CYCLE 1')
      dt = session%model%mech%dt
      associate (bl => session%model%geometry%blocks, co => session%model%geometry%contacts)
         top = 0
         do b = 1, bl%n
            if (bl%live(b) .and. bl%sdef(b)) top = b
         end do
         call check(top > 0 .and. count(bl%live(1:bl%n) .and. bl%sdef(1:bl%n)) == 1, &
                    trim(tag)//': one SDEF block')
         if (top == 0) return
         call check(abs(bl%area(top) - 1.0_wp) < 1.0e-2_wp, trim(tag)//': the SDEF block is the unit square')
         d11 = kb + 4.0_wp*gb/3.0_wp
         d12 = kb - 2.0_wp*gb/3.0_wp
         ! masses of the (rounded) unit square
         mass = [rho, rho, rho/6.0_wp, rho/12.0_wp, rho/12.0_wp, rho/6.0_wp]
         kmat = 0.0_wp
         kmat(4, 4) = d11; kmat(5, 5) = d11; kmat(4, 5) = d12; kmat(5, 4) = d12
         kmat(6, 6) = 4.0_wp*gb
         kmat = kmat*bl%area(top)
         ncontact = 0
         lsum = 0.0_wp
         do c = 1, co%n
            if (.not. co%live(c)) cycle
            if (co%block1(c) /= top .and. co%block2(c) /= top) cycle
            ncontact = ncontact + 1
            l = co%length(c)
            lsum = lsum + l
            rx = co%x(c) - bl%xc(top)
            ry = co%y(c) - bl%yc(top)
            ! normal and joint directions: the displacement of the point
            ! along (tx, ty) is q . (u, v, theta, exx, eyy, exy)
            tx = co%nx(c); ty = co%ny(c)
            q = [tx, ty, -ry*tx + rx*ty, rx*tx, ry*ty, ry*tx + rx*ty]
            kmat = kmat + jkn*l*spread(q, 2, 6)*spread(q, 1, 6)
            tx = -co%ny(c); ty = co%nx(c)
            q = [tx, ty, -ry*tx + rx*ty, rx*tx, ry*ty, ry*tx + rx*ty]
            kmat = kmat + 0.1_wp*jkn*l*spread(q, 2, 6)*spread(q, 1, 6)
         end do
         call check(ncontact == 2, trim(tag)//': the joint is two corner contacts')
         call check(abs(lsum - 1.0_wp) < 1.0e-2_wp, trim(tag)//': their lengths make the 1 m joint')
      end associate
      crit = 2.0_wp/sqrt(largest_root(kmat, mass))
      write (*, '(a,es11.4,a,es11.4,a,f6.3)') trim(tag)//': dt ', dt, '  dt_crit ', crit, &
         '  ratio ', dt/crit
      call check(dt <= crit, trim(tag)//': the step does not exceed the critical step')
      call check(dt >= lower*crit, trim(tag)//': the step is not far below the critical step')
   end subroutine case

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   !> Largest lambda with det(K - lambda M) = 0, M diagonal, by bisection on
   !> the number of negative pivots of K - lambda M (all six above it).
   real(wp) function largest_root(k, m) result(lam)
      real(wp), intent(in) :: k(6, 6), m(6)
      real(wp) :: lo, hi
      integer :: it, i
      lo = 0.0_wp
      hi = 0.0_wp
      do i = 1, 6
         hi = hi + k(i, i)/m(i)        ! the trace of M^-1 K bounds every root
      end do
      hi = 1.01_wp*hi
      do it = 1, 200
         lam = 0.5_wp*(lo + hi)
         if (negative_pivots(k, m, lam) < 6) then
            lo = lam
         else
            hi = lam
         end if
      end do
      lam = hi
   end function largest_root

   integer function negative_pivots(k, m, lam) result(n)
      real(wp), intent(in) :: k(6, 6), m(6), lam
      real(wp) :: a(6, 6)
      integer :: i, j
      a = k
      do i = 1, 6
         a(i, i) = a(i, i) - lam*m(i)
      end do
      n = 0
      do i = 1, 6
         if (a(i, i) < 0.0_wp) n = n + 1
         if (a(i, i) == 0.0_wp) cycle
         do j = i + 1, 6
            a(j, i + 1:6) = a(j, i + 1:6) - a(j, i)/a(i, i)*a(i, i + 1:6)
         end do
      end do
   end function negative_pivots

end program test_sdef_timestep
