!> Joint laws against closed-form answers (manual Section 3.3, Eqs. 4-8, 10-17).
program test_joint_law
   use core_kinds, only: wp
   use core_error, only: error_t
   use testing, only: check, check_close, testing_finish
   use contact_joint_law, only: joint_law_t, joint_props_t, joint_state_t, joint_law_create, &
                                known_jcons, state_slip, state_tension, state_fractured
   implicit none
   class(joint_law_t), allocatable :: law
   type(joint_props_t) :: p
   type(joint_state_t) :: s
   type(error_t), allocatable :: error
   integer :: k, step
   real(wp), parameter :: length = 2.0_wp

   ! Factory: every listed JCONS builds; an unknown one names the known ones.
   do k = 1, size(known_jcons)
      call joint_law_create(known_jcons(k), law, error)
      call check(.not. allocated(error) .and. allocated(law), 'factory builds a known JCONS')
      if (allocated(law)) call check(law%jcons == known_jcons(k), 'law knows its JCONS')
   end do
   call joint_law_create(4, law, error)
   call check(allocated(error), 'JCONS 4 is unknown')
   if (allocated(error)) call check(index(error%message, '1, 2, 3, 5') > 0, 'error lists known')

   ! JCONS 2: stresses times length. Closing by 1e-4 with JKN 1e6 on L = 2:
   ! Fn = JKN * L * 1e-4 = 200 (compression positive, opening displacement positive).
   call joint_law_create(2, law, error)
   p = joint_props_t(kn=1.0e6_wp, ks=1.0e6_wp, friction=0.5_wp)
   call fresh()
   call step1(-1.0e-4_wp, 0.0_wp)
   call check_close(s%fn(1), 200.0_wp, 1.0e-12_wp, 'JCONS 2 normal force = JKN L dun')
   call check_close(s%un(1), -1.0e-4_wp, 1.0e-12_wp, 'normal displacement accumulates')
   ! Shear in steps of 1e-5: elastic Fs = JKS L us until Fs = Fn tan(phi) = 100.
   call step1(0.0_wp, 1.0e-5_wp)
   call check_close(s%fs(1), 20.0_wp, 1.0e-12_wp, 'elastic shear force = JKS L dus')
   call check(iand(s%flags(1), state_slip) == 0, 'elastic: no slip flag')
   do step = 1, 10
      call step1(0.0_wp, 1.0e-5_wp)
   end do
   call check_close(s%fs(1), 100.0_wp, 1.0e-12_wp, 'shear force capped at c L + Fn tan(phi)')
   call check(iand(s%flags(1), state_slip) /= 0, 'slip flag set at the limit')
   call step1(0.0_wp, -1.0e-5_wp)
   call check_close(s%fs(1), 80.0_wp, 1.0e-12_wp, 'elastic unloading after slip')

   ! Cohesion: limit = JCOH L + Fn tan(phi) = 10*2 + 100 = 120.
   p%cohesion = 10.0_wp
   call fresh()
   call step1(-1.0e-4_wp, 0.0_wp)
   do step = 1, 20
      call step1(0.0_wp, 1.0e-5_wp)
   end do
   call check_close(s%fs(1), 120.0_wp, 1.0e-12_wp, 'cohesion adds JCOH L to the limit')

   ! Tension: JTENS 5 on L = 2 holds Fn down to -10; beyond, the contact opens.
   p = joint_props_t(kn=1.0e6_wp, ks=1.0e6_wp, friction=0.5_wp, tension=5.0_wp)
   call fresh()
   call step1(4.0e-6_wp, 0.0_wp)
   call check_close(s%fn(1), -8.0_wp, 1.0e-12_wp, 'tensile normal force below the limit')
   call check(iand(s%flags(1), state_tension) == 0, 'no tensile failure yet')
   call step1(2.0e-6_wp, 0.0_wp)
   call check_close(s%fn(1), 0.0_wp, 0.0_wp, 'tensile failure drops the normal force')
   call check(iand(s%flags(1), state_tension) /= 0, 'tension flag')

   ! Dilation: slip of du with tan(psi) = 0.1 raises Fn by JKN L 0.1 du.
   p = joint_props_t(kn=1.0e6_wp, ks=1.0e6_wp, friction=0.5_wp, dilation=0.1_wp)
   call fresh()
   call step1(-1.0e-4_wp, 0.0_wp)                 ! Fn = 200, limit 100 -> elastic to 5e-5
   call step1(0.0_wp, 5.0e-5_wp)
   call check_close(s%fn(1), 200.0_wp, 1.0e-12_wp, 'no dilation while elastic')
   call step1(0.0_wp, 1.0e-5_wp)                  ! fully sliding increment
   call check_close(s%fn(1), 200.0_wp + 1.0e6_wp*length*0.1_wp*1.0e-5_wp, 1.0e-12_wp, &
                    'dilation increment = JKN L tan(psi) du_slip')

   ! JCONS 5: a joint that slipped is fractured; cohesion and tension are gone.
   call joint_law_create(5, law, error)
   p = joint_props_t(kn=1.0e6_wp, ks=1.0e6_wp, friction=0.5_wp, cohesion=10.0_wp, &
                     tension=5.0_wp)
   call fresh()
   call step1(-1.0e-4_wp, 0.0_wp)
   do step = 1, 20
      call step1(0.0_wp, 1.0e-5_wp)
   end do
   call check(iand(s%flags(1), state_fractured) /= 0, 'JCONS 5 fracture flag after slip')
   call step1(0.0_wp, 1.0e-5_wp)
   call check_close(s%fs(1), 100.0_wp, 1.0e-12_wp, 'fractured: limit is Fn tan(phi) only')
   call step1(1.0e-4_wp + 1.0e-7_wp, 0.0_wp)
   call check_close(s%fn(1), 0.0_wp, 0.0_wp, 'fractured: no tensile strength left')

   ! JCONS 1: point contact, forces directly (length ignored).
   call joint_law_create(1, law, error)
   p = joint_props_t(kn=1.0e6_wp, ks=1.0e6_wp, friction=0.5_wp)
   call fresh()
   call step1(-1.0e-4_wp, 0.0_wp)
   call check_close(s%fn(1), 100.0_wp, 1.0e-12_wp, 'JCONS 1 normal force = KN dun')

   ! JCONS 3 under constant normal stress: with small roughness JR the
   ! effective friction decays to the basic angle (Eq. 17), so the shear stress
   ! tends to sigma_n tan(phi).
   call joint_law_create(3, law, error)
   p = joint_props_t(kn=1.0e9_wp, ks=1.0e8_wp, friction=tan(30.0_wp*acos(-1.0_wp)/180.0_wp), &
                     initial_friction=45.0_wp*acos(-1.0_wp)/180.0_wp, roughness=1.0e-4_wp)
   call fresh()
   call step1(-1.0e-3_wp, 0.0_wp)                 ! sigma_n = 1e6 on L = 2
   ! 0.1 of shear = 17 decay lengths tau/ks of the approach to the bound
   do step = 1, 10000
      call step1(0.0_wp, 1.0e-5_wp)
   end do
   call check_close(s%fs(1)/length, 1.0e6_wp*tan(30.0_wp*acos(-1.0_wp)/180.0_wp), 1.0e-2_wp, &
                    'JCONS 3 residual shear stress = sigma_n tan(phi) within 1 %')
   call check(s%phi_eff(1) < 31.0_wp*acos(-1.0_wp)/180.0_wp, 'JCONS 3 friction degraded')
   call testing_finish()

contains

   subroutine fresh()
      if (allocated(s%fn)) deallocate (s%fn, s%fs, s%un, s%us, s%flags, s%phi_eff, &
                                       s%reversal, s%dus_old)
      allocate (s%fn(1), s%fs(1), s%un(1), s%us(1), s%flags(1), s%phi_eff(1), s%reversal(1), &
                s%dus_old(1))
      s%fn = 0; s%fs = 0; s%un = 0; s%us = 0; s%flags = 0
      s%phi_eff = 0; s%reversal = 0; s%dus_old = 0
   end subroutine fresh

   subroutine step1(dun, dus)
      real(wp), intent(in) :: dun, dus
      call law%update(p, [1], 1, [length], [dun], [dus], s)
   end subroutine step1

end program test_joint_law
