!> Joint constitutive laws (manual Section 3.3, CHANGE JCONS): the force
!> increment at each contact from its relative displacement increment.
!>
!> Sign conventions (manual Section 4.1): normal displacement is positive in
!> opening, normal force positive in compression, so dFn = -Kn dUn.
!>   JCONS 1  point contact: KN KS [force/disp], CCOH CTENS [force], CFRIC CDIL
!>   JCONS 2  area contact:  JKN JKS [stress/disp], JCOH JTENS [stress], JFRIC JDIL;
!>            forces are stresses times the contact length (Eq. 5-6)
!>   JCONS 5  as 2, but a contact that fails in tension or shear is flagged
!>            fractured and loses cohesion and tension for good
!>   JCONS 3  continuously-yielding joint (Eqs. 10-18; JKN JKS JEN JES JFRIC JIF JR)
!>
!> Each law is one type behind `joint_law_t`; `update` is called once per group of
!> contacts sharing a law, with the loop over the group inside the kernel (no
!> polymorphic call per contact).
module contact_joint_law
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use model_geometry, only: joint_state_t
   implicit none
   private
   public :: joint_law_t, joint_props_t, joint_state_t, joint_law_create, known_jcons
   public :: joint_mohr_coulomb_t, joint_yielding_t
   public :: state_slip, state_tension, state_fractured

   !> JCONS numbers the factory knows.
   integer, parameter :: known_jcons(4) = [1, 2, 3, 5]

   !> Bits of the per-contact state word.
   integer, parameter :: state_slip = 1, state_tension = 2, state_fractured = 4

   !> Properties of one joint material in the units of its law.
   type :: joint_props_t
      real(wp) :: kn = 0.0_wp, ks = 0.0_wp
      real(wp) :: cohesion = 0.0_wp, friction = 0.0_wp  !< friction = tan(phi)
      real(wp) :: tension = 0.0_wp, dilation = 0.0_wp   !< dilation = tan(psi)
      real(wp) :: en = 0.0_wp, es = 0.0_wp              !< JEN, JES (JCONS 3)
      real(wp) :: initial_friction = 0.0_wp             !< JIF [radians] (JCONS 3)
      real(wp) :: roughness = 0.0_wp                    !< JR [length] (JCONS 3)
   end type joint_props_t


   type, abstract :: joint_law_t
      integer :: jcons = 0
   contains
      procedure(update_interface), deferred :: update
   end type joint_law_t

   abstract interface
      !> Update contacts idx(1:n). `length` is the effective contact length
      !> (ignored by point contacts); dun, dus are this step's displacement
      !> increments at those contacts (same order as idx).
      subroutine update_interface(this, props, idx, n, length, dun, dus, state)
         import :: joint_law_t, joint_props_t, joint_state_t, wp
         class(joint_law_t), intent(in) :: this
         type(joint_props_t), intent(in) :: props
         integer, intent(in) :: n
         integer, intent(in) :: idx(n)
         real(wp), intent(in) :: length(n), dun(n), dus(n)
         type(joint_state_t), intent(inout) :: state
      end subroutine update_interface
   end interface

   !> JCONS 1, 2 and 5: elastic / Mohr-Coulomb slip with tension cut-off.
   type, extends(joint_law_t) :: joint_mohr_coulomb_t
      logical :: per_length = .true.    !< JCONS 2, 5: stress laws times length
      logical :: fracture_flag = .false. !< JCONS 5
   contains
      procedure :: update => mohr_coulomb_update
   end type joint_mohr_coulomb_t

   !> JCONS 3: continuously-yielding joint (Cundall and Hart 1984, Lemos 1987).
   type, extends(joint_law_t) :: joint_yielding_t
   contains
      procedure :: update => yielding_update
   end type joint_yielding_t

contains

   !> Build the law for a JCONS number; an unknown number is an error naming
   !> the known ones.
   subroutine joint_law_create(jcons, law, error)
      integer, intent(in) :: jcons
      class(joint_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      select case (jcons)
      case (1)
         allocate (law, source=joint_mohr_coulomb_t(jcons=1, per_length=.false.))
      case (2)
         allocate (law, source=joint_mohr_coulomb_t(jcons=2, per_length=.true.))
      case (5)
         allocate (law, source=joint_mohr_coulomb_t(jcons=5, per_length=.true., &
                                                     fracture_flag=.true.))
      case (3)
         allocate (law, source=joint_yielding_t(jcons=3))
      case default
         call set_error(error, 'unknown joint constitutive number JCONS; known: 1, 2, 3, 5')
      end select
   end subroutine joint_law_create

   subroutine mohr_coulomb_update(this, props, idx, n, length, dun, dus, state)
      class(joint_mohr_coulomb_t), intent(in) :: this
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: n
      integer, intent(in) :: idx(n)
      real(wp), intent(in) :: length(n), dun(n), dus(n)
      type(joint_state_t), intent(inout) :: state
      integer :: i, c
      real(wp) :: scale, kn, ks, fn, fs, coh, tens, fsmax, slip, excess
      logical :: fractured
      do i = 1, n
         c = idx(i)
         scale = 1.0_wp
         if (this%per_length) scale = length(i)
         kn = props%kn*scale
         ks = props%ks*scale
         fractured = this%fracture_flag .and. iand(state%flags(c), state_fractured) /= 0
         if (fractured) then
            coh = 0.0_wp
            tens = 0.0_wp
         else
            coh = props%cohesion*scale
            tens = props%tension*scale
         end if
         state%un(c) = state%un(c) + dun(i)
         state%us(c) = state%us(c) + dus(i)
         fn = state%fn(c) - kn*dun(i)
         fs = state%fs(c) + ks*dus(i)
         state%flags(c) = iand(state%flags(c), state_fractured)
         if (fn < -tens) then                        ! tensile failure: contact opens
            fn = 0.0_wp
            fs = 0.0_wp
            state%flags(c) = ior(state%flags(c), state_tension)
            if (this%fracture_flag) state%flags(c) = ior(state%flags(c), state_fractured)
         else
            ! Mohr-Coulomb slip (Eq. 8) when |fs| exceeds the strength; a
            ! contact in tension within JTENS has strength max(c + fn tan phi, 0).
            ! The shear is capped at the strength; the contact counts as
            ! slipping (flag, dilation, JCONS 5 fracture) only when the excess
            ! is more than round-off, so that a joint with JCOH 0 holding a
            ! block by JTENS alone, shear zero up to round-off, keeps its bond.
            fsmax = max(coh + fn*props%friction, 0.0_wp)
            if (abs(fs) > fsmax) then
               slip = (abs(fs) - fsmax)/max(ks, tiny(1.0_wp))
               excess = abs(fs) - fsmax
               fs = sign(fsmax, fs)
               if (excess > 1.0e-9_wp*(abs(fn) + coh + tens)) then
                  ! Dilation: the sliding part of the increment opens the joint by
                  ! tan(psi)|du_s|, which raises the normal force under confinement.
                  if (props%dilation > 0.0_wp) fn = fn + kn*props%dilation*min(slip, abs(dus(i)))
                  state%flags(c) = ior(state%flags(c), state_slip)
                  if (this%fracture_flag) state%flags(c) = ior(state%flags(c), state_fractured)
               end if
            end if
         end if
         state%fn(c) = fn
         state%fs(c) = fs
      end do
   end subroutine mohr_coulomb_update

   !> Continuously-yielding joint, Eqs. 10-18. Stiffnesses k = a sigma_n^e
   !> (a = JKN/JKS, e = JEN/JES; e = 0 gives constant stiffness).
   subroutine yielding_update(this, props, idx, n, length, dun, dus, state)
      class(joint_yielding_t), intent(in) :: this
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: n
      integer, intent(in) :: idx(n)
      real(wp), intent(in) :: length(n), dun(n), dus(n)
      type(joint_state_t), intent(inout) :: state
      integer :: i, c
      real(wp) :: sn, ss, kn, ks, tau_m, f, r, phi, dusp, l
      real(wp), parameter :: r_max = 0.75_wp
      if (this%jcons /= 3) return
      phi = atan(props%friction)
      do i = 1, n
         c = idx(i)
         l = max(length(i), tiny(1.0_wp))
         sn = state%fn(c)/l                          ! compression positive
         ss = state%fs(c)/l
         if (state%phi_eff(c) <= 0.0_wp) state%phi_eff(c) = max(props%initial_friction, phi)
         kn = props%kn*max(sn, 0.0_wp)**props%en
         if (props%en /= 0.0_wp .and. sn <= 0.0_wp) kn = props%kn
         ks = props%ks*max(sn, 0.0_wp)**props%es
         if (props%es /= 0.0_wp .and. sn <= 0.0_wp) ks = props%ks
         state%un(c) = state%un(c) + dun(i)
         state%us(c) = state%us(c) + dus(i)
         sn = sn - kn*dun(i)                          ! Eq. 10
         if (sn <= 0.0_wp) then                       ! no tensile strength
            state%fn(c) = 0.0_wp
            state%fs(c) = 0.0_wp
            state%flags(c) = state_tension
            state%dus_old(c) = dus(i)
            cycle
         end if
         if (dus(i) == 0.0_wp) then
            state%fn(c) = sn*l
            state%flags(c) = 0
            cycle
         end if
         tau_m = sn*tan(state%phi_eff(c))*sign(1.0_wp, dus(i))      ! Eq. 14
         r = state%reversal(c)
         if (sign(1.0_wp, dus(i)) /= sign(1.0_wp, state%dus_old(c)) .and. &
             state%dus_old(c) /= 0.0_wp) r = min(ss/tau_m, r_max)     ! load reversal
         r = max(min(r, r_max), 0.0_wp)
         f = (1.0_wp - ss/tau_m)/(1.0_wp - r)                        ! Eq. 13
         ss = ss + f*ks*dus(i)                                         ! Eq. 11
         dusp = (1.0_wp - f)*dus(i)                                    ! Eq. 16
         if (props%roughness > 0.0_wp) state%phi_eff(c) = state%phi_eff(c) &
            - (state%phi_eff(c) - phi)*abs(dusp)/props%roughness      ! Eq. 15
         state%reversal(c) = r
         state%dus_old(c) = dus(i)
         state%flags(c) = merge(state_slip, 0, f < 1.0_wp)
         state%fn(c) = sn*l
         state%fs(c) = ss*l
      end do
   end subroutine yielding_update

end module contact_joint_law
