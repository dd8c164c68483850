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
   use core_kinds, only: wp, ip
   use, intrinsic :: iso_fortran_env, only: int8   ! core_kinds%i1 (i0, i1 name loop bounds here)
   use core_error, only: error_t, set_error
   use model_geometry, only: joint_state_t, joint_state_value
   implicit none
   private
   public :: joint_law_t, joint_props_t, joint_state_t, joint_law_create, known_jcons
   public :: joint_mohr_coulomb_t, joint_yielding_t, yielding_stiffness, state_dependent
   public :: state_slip, state_tension, state_fractured, joint_shear_ratio
   public :: mohr_coulomb_rigid_kernel, mohr_coulomb_rigid_split

   !> JCONS numbers the factory knows.
   integer, parameter :: known_jcons(4) = [1, 2, 3, 5]

   !> Bits of the per-contact state word (one byte: joint_state_t%flags).
   integer(int8), parameter :: state_slip = 1_int8, state_tension = 2_int8, state_fractured = 4_int8

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
      subroutine update_interface(this, props, idx, n, length, dun, dus, state, kmax)
         import :: joint_law_t, joint_props_t, joint_state_t, wp
         class(joint_law_t), intent(in) :: this
         type(joint_props_t), intent(in) :: props
         integer, intent(in) :: n
         integer, intent(in) :: idx(n)
         real(wp), intent(in) :: length(n), dun(n), dus(n)
         type(joint_state_t), intent(inout) :: state
         !> raised to the largest stiffness [force/length] of the updated
         !> contacts at their next step, by laws whose stiffness depends on
         !> their state (JCONS 3); the others leave it alone
         real(wp), intent(inout) :: kmax
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

   subroutine mohr_coulomb_update(this, props, idx, n, length, dun, dus, state, kmax)
      class(joint_mohr_coulomb_t), intent(in) :: this
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: n
      integer, intent(in) :: idx(n)
      real(wp), intent(in) :: length(n), dun(n), dus(n)
      type(joint_state_t), intent(inout) :: state
      real(wp), intent(inout) :: kmax   ! constant stiffness: counted from the properties
      integer :: i, c
      logical :: dilate
      real(wp) :: ud
      dilate = props%dilation > 0.0_wp
      ! ud exists once a group dilates (contact_groups_build, joint_state_ud);
      ! this is the fallback for a caller that hands the law a state of its own
      if (dilate .and. .not. allocated(state%ud)) allocate (state%ud(size(state%fn)), source=0.0_wp)
      do i = 1, n
         c = idx(i)
         ud = joint_state_value(state%ud, int(c, ip))
         call mohr_coulomb_contact(props, this%per_length, this%fracture_flag, dilate, length(i), &
                                   dun(i), dus(i), state%fn(c), state%fs(c), state%un(c), &
                                   state%us(c), state%flags(c), ud)
         ! (only a dilating law changes it)
         if (dilate) state%ud(c) = ud
      end do
   end subroutine mohr_coulomb_update

   !> One contact of mohr_coulomb_update (JCONS 1, 2, 5): `length` the
   !> effective contact length (used when `per_length`), dun, dus this step's
   !> increments; forces, accumulated displacements and the state word are
   !> updated in place; `ud` (the dilation ridden up) grows by the opening
   !> the dilation gives. `dilate` is props%dilation > 0 (an argument so
   !> that a loop can be compiled for the value it has in all its contacts).
   pure subroutine mohr_coulomb_contact(props, per_length, fracture_flag, dilate, length, dun, &
                                        dus, fn, fs, un, us, flags, ud)
      type(joint_props_t), intent(in) :: props
      logical, intent(in) :: per_length, fracture_flag, dilate
      real(wp), intent(in) :: length, dun, dus
      real(wp), intent(inout) :: fn, fs, un, us, ud
      integer(int8), intent(inout) :: flags
      real(wp) :: scale, kn, ks, coh, tens, fsmax, slip, excess, opening
      logical :: loaded
      logical :: fractured
      scale = 1.0_wp
      if (per_length) scale = length
      kn = props%kn*scale
      ks = props%ks*scale
      fractured = fracture_flag .and. iand(flags, state_fractured) /= 0
      if (fractured) then
         coh = 0.0_wp
         tens = 0.0_wp
      else
         coh = props%cohesion*scale
         tens = props%tension*scale
      end if
      un = un + dun
      us = us + dus
      fn = fn - kn*dun
      fs = fs + ks*dus
      flags = iand(flags, state_fractured)
      ! Dilation (JDIL = tan(psi)): the sliding part s of the shear increment
      ! opens the joint by tan(psi) s, which raises the normal force by
      ! kn tan(psi) s under confinement. The slip is found with that rise
      ! (|fs| - ks s = c + tan(phi) (fn + kn tan(psi) s), the return to the
      ! strength of the non-associated Coulomb law), and the tension check
      ! below sees the normal force after it: a joint sliding fast enough
      ! that one step's dilation, kn tan(psi) |du_s|, matches its normal force
      ! (the block rising by that much a step) otherwise showed a normal force
      ! near zero before the dilation, so its friction faded with the speed
      ! (to 3 % of tan(phi) sigma_n at 1.3 m/s in probe_rigid_decks'
      ! dilation deck) and the contacts opened in tension. The opening is
      ! tan(psi) times the whole plastic slip s, which exceeds the step's
      ! |du_s| where the strength fell within the step (the normal force
      ! dropping while the joint slides): capped at |du_s|, a sliding block
      ! ringing normal to its joint rose 0.3 % (DAMP AUTO) to 3 % (undamped)
      ! less than tan(psi) per unit of slip (e2e.camp8_decks).
      opening = 0.0_wp
      if (dilate) then
         fsmax = max(coh + fn*props%friction, 0.0_wp)
         excess = abs(fs) - fsmax
         if (excess > 1.0e-9_wp*(abs(fn) + coh + tens)) then
            slip = excess/max(ks + props%friction*kn*props%dilation, tiny(1.0_wp))
            opening = props%dilation*slip
            fn = fn + kn*opening
         end if
      end if
      if (fn < -tens) then                        ! tensile failure: contact opens
         fn = 0.0_wp
         fs = 0.0_wp
         flags = ior(flags, state_tension)
         if (fracture_flag) flags = ior(flags, state_fractured)
      else
         ! Mohr-Coulomb slip (Eq. 8) when |fs| exceeds the strength; a
         ! contact in tension within JTENS has strength max(c + fn tan phi, 0).
         ! The shear is capped at the strength; the contact counts as
         ! slipping (flag, dilation, JCONS 5 fracture) only when the excess
         ! is more than round-off, so that a joint with JCOH 0 holding a
         ! block by JTENS alone, shear zero up to round-off, keeps its bond.
         ! A contact with no strength and no normal force carries nothing
         ! and is not counted as slipping: a corner meeting a corner where
         ! a joint ends has no length of its own, takes no INSITU force
         ! (the joint's stress is on its neighbours' lengths), and its
         ! CLEMIN stiffness moves its shear by round-off; flagged, every
         ! such contact of a still, stressed model showed as at slip.
         fsmax = max(coh + fn*props%friction, 0.0_wp)
         if (abs(fs) > fsmax) then
            excess = abs(fs) - fsmax
            fs = sign(fsmax, fs)
            if (excess > 1.0e-9_wp*(abs(fn) + coh + tens)) then
               loaded = fsmax > 0.0_wp .or. fn > 0.0_wp
               if (loaded) then
                  flags = ior(flags, state_slip)
                  if (fracture_flag) flags = ior(flags, state_fractured)
               end if
            end if
         end if
         ! the dilation ridden up: the asperities fill that much of the gap
         ! (added only when not 0: ud is never -0, so ud + 0 would be ud; a
         ! contact that does not dilate neither loads nor stores it)
         if (opening /= 0.0_wp) ud = ud + opening
      end if
   end subroutine mohr_coulomb_contact

   !> One contact of the rigid Mohr-Coulomb loops (mohr_coulomb_rigid_kernel
   !> on one thread, mohr_coulomb_rigid_split on more): contact c between the
   !> rigid blocks b1 and b2 at its point (px, py): displacement increments
   !> from the block velocities, the law (mohr_coulomb_contact), the
   !> stiffness-proportional dashpots; returns the force (fx, fy) on block2
   !> (block1 takes -fx, -fy), which the callers add to the blocks. Same
   !> order and expressions as contact_force_pass's general loops. Small and
   !> pure, so that the compiler inlines it (and the law) into both loops.
   !> `dilate` is props%dilation > 0, `damped` beta > 0 (see rigid_kernel_loop);
   !> `has_ud` false: the model has no ud (joint_state_ud), read as 0 and
   !> never written (no law of the model dilates).
   pure subroutine mohr_coulomb_rigid_contact(c, b1, b2, px, py, cnx, cny, cgap, clen, fn, fs, &
                                              un, us, flags, ud, has_ud, bp, gap_new, props, &
                                              per_length, fracture_flag, dilate, damped, dt, &
                                              geometric, gap_tol, clemin, beta, fx, fy)
      integer(ip), intent(in) :: c, b1, b2
      real(wp), intent(in) :: px, py
      real(wp), intent(in) :: cnx(*), cny(*), clen(*)
      real(wp), intent(inout) :: cgap(*), fn(*), fs(*), un(*), us(*), ud(*)
      logical, intent(in) :: has_ud
      integer(int8), intent(inout) :: flags(*)
      real(wp), intent(in) :: bp(8, *)
      real(wp), intent(inout) :: gap_new(*)
      type(joint_props_t), intent(in) :: props
      logical, intent(in) :: per_length, fracture_flag, dilate, damped, geometric
      real(wp), intent(in) :: dt, gap_tol, clemin, beta
      real(wp), intent(out) :: fx, fy
      real(wp) :: v1x, v1y, v2x, v2y, rvx, rvy, nx, ny, tx, ty, vn, vs
      real(wp) :: gold, gnew, l, dun, dus, lbeta, dopen, udc
      logical :: gap_open
      nx = cnx(c)
      ny = cny(c)
      ! bp(1:5, b) = vx, vy, vr, xc, yc of block b
      v1x = bp(1, b1) - bp(3, b1)*(py - bp(5, b1))
      v1y = bp(2, b1) + bp(3, b1)*(px - bp(4, b1))
      v2x = bp(1, b2) - bp(3, b2)*(py - bp(5, b2))
      v2y = bp(2, b2) + bp(3, b2)*(px - bp(4, b2))
      rvx = v2x - v1x
      rvy = v2y - v1y
      vs = -rvx*ny + rvy*nx
      dus = vs*dt
      gold = cgap(c)
      if (geometric) then
         gnew = gap_new(c)
      else
         gnew = gold + (rvx*nx + rvy*ny)*dt
         gap_new(c) = gnew
      end if
      ! (ud read only for a contact without normal force: the two tests of
      ! contact_force_pass, one after the other)
      ! (x - 0 is x to the last bit: a model without ud gives the same values)
      udc = 0.0_wp
      if (has_ud) udc = ud(c)
      gap_open = .false.
      if (fn(c) == 0.0_wp) gap_open = gold - udc > gap_tol
      if (gap_open) then
         dun = min(gnew - udc, 0.0_wp)
         ! the rest of the gap change, for un after the law: worked out here,
         ! one value kept across the inlined law instead of gnew, gold and
         ! dun (-0.24 M instructions a step at 10k blocks, same values)
         dopen = (gnew - gold) - dun
         if (gnew - udc > gap_tol) then
            ! still open: no shear either (as contact_force_pass)
            dus = 0.0_wp
            fs(c) = 0.0_wp
         end if
      else
         dun = gnew - gold
      end if
      l = max(clen(c), clemin)
      call mohr_coulomb_contact(props, per_length, fracture_flag, dilate, l, dun, dus, &
                                fn(c), fs(c), un(c), us(c), flags(c), udc)
      if (has_ud .and. dilate) ud(c) = udc
      ! un takes the whole gap change (as contact_force_pass)
      if (gap_open) un(c) = un(c) + dopen
      ! force (as contact_force_pass)
      cgap(c) = gnew
      tx = -ny
      ty = nx
      fx = fn(c)*nx - fs(c)*tx
      fy = fn(c)*ny - fs(c)*ty
      if (damped .and. fn(c) > 0.0_wp) then
         lbeta = 1.0_wp
         if (per_length) lbeta = l
         vn = -dun/dt
         vs = dus/dt
         fx = fx + beta*props%kn*lbeta*vn*nx
         fy = fy + beta*props%kn*lbeta*vn*ny
         if (iand(flags(c), state_slip) == 0) then
            fx = fx - beta*props%ks*lbeta*vs*tx
            fy = fy - beta*props%ks*lbeta*vs*ty
         end if
      end if
   end subroutine mohr_coulomb_rigid_contact

   !> The loop of contact_mechanics' rigid_group_pass over group entries
   !> i0..i1 (contacts gidx(i)) of one Mohr-Coulomb group when every block is
   !> rigid: each contact (mohr_coulomb_rigid_contact) and its force and
   !> moment sums into the blocks. bp(1:8, b) = vx, vy, vr, xc, yc, fx, fy,
   !> fm of block b (contact_mechanics' block_pack: one cache line a block
   !> instead of one in each of eight arrays).
   !> The common group (JCONS 2 without JDIL, no stiffness-proportional
   !> damping, the geometric gap every step) runs rigid_kernel_loop with its
   !> five switches as constants: gfortran inlines both calls and drops the
   !> tests from that copy of the loop (34 instructions a contact fewer of
   !> 181 on rigid_bench's wall); the values are the same. (A third call, a
   !> copy for JCONS 1, made gfortran 12 merge the calls into one call of the
   !> loop with the switches as variables: none was specialised.)
   subroutine mohr_coulomb_rigid_kernel(i0, i1, gidx, block1, block2, cx, cy, cnx, cny, cgap, &
                                        clen, fn, fs, un, us, flags, ud, has_ud, bp, gap_new, props, &
                                        per_length, fracture_flag, dt, geometric, gap_tol, clemin, &
                                        beta)
      integer, intent(in) :: i0, i1
      integer, intent(in) :: gidx(*)
      integer(ip), intent(in) :: block1(*), block2(*)
      real(wp), intent(in) :: cx(*), cy(*), cnx(*), cny(*), clen(*)
      real(wp), intent(inout) :: cgap(*), fn(*), fs(*), un(*), us(*), ud(*)
      logical, intent(in) :: has_ud
      integer(int8), intent(inout) :: flags(*)
      real(wp), intent(inout) :: bp(8, *), gap_new(*)
      type(joint_props_t), intent(in) :: props
      logical, intent(in) :: per_length, fracture_flag, geometric
      real(wp), intent(in) :: dt, gap_tol, clemin, beta
      logical :: dilate, damped
      dilate = props%dilation > 0.0_wp
      damped = beta > 0.0_wp
      if (per_length .and. .not. fracture_flag .and. .not. dilate .and. .not. damped .and. &
          geometric .and. .not. has_ud) then
         call rigid_kernel_loop(i0, i1, gidx, block1, block2, cx, cy, cnx, cny, cgap, clen, fn, fs, &
                                un, us, flags, ud, .false., bp, gap_new, props, .true., .false., &
                                .false., .false., dt, .true., gap_tol, clemin, beta)
      else
         call rigid_kernel_loop(i0, i1, gidx, block1, block2, cx, cy, cnx, cny, cgap, clen, fn, fs, &
                                un, us, flags, ud, has_ud, bp, gap_new, props, per_length, &
                                fracture_flag, dilate, damped, dt, geometric, gap_tol, clemin, beta)
      end if
   end subroutine mohr_coulomb_rigid_kernel

   !> The loop of mohr_coulomb_rigid_kernel.
   subroutine rigid_kernel_loop(i0, i1, gidx, block1, block2, cx, cy, cnx, cny, cgap, clen, fn, &
                                fs, un, us, flags, ud, has_ud, bp, gap_new, props, per_length, &
                                fracture_flag, dilate, damped, dt, geometric, gap_tol, clemin, beta)
      integer, intent(in) :: i0, i1
      integer, intent(in) :: gidx(*)
      integer(ip), intent(in) :: block1(*), block2(*)
      real(wp), intent(in) :: cx(*), cy(*), cnx(*), cny(*), clen(*)
      real(wp), intent(inout) :: cgap(*), fn(*), fs(*), un(*), us(*), ud(*)
      logical, intent(in) :: has_ud
      integer(int8), intent(inout) :: flags(*)
      real(wp), intent(inout) :: bp(8, *), gap_new(*)
      type(joint_props_t), intent(in) :: props
      logical, intent(in) :: per_length, fracture_flag, dilate, damped, geometric
      real(wp), intent(in) :: dt, gap_tol, clemin, beta
      integer :: i
      integer(ip) :: c, b1, b2
      real(wp) :: px, py, fx, fy
      do i = i0, i1
         c = gidx(i)
         b1 = block1(c)
         b2 = block2(c)
         px = cx(c)
         py = cy(c)
         call mohr_coulomb_rigid_contact(c, b1, b2, px, py, cnx, cny, cgap, clen, fn, fs, un, us, &
                                         flags, ud, has_ud, bp, gap_new, props, per_length, &
                                         fracture_flag, dilate, damped, dt, geometric, gap_tol, &
                                         clemin, beta, fx, fy)
         bp(6, b2) = bp(6, b2) + fx
         bp(7, b2) = bp(7, b2) + fy
         bp(8, b2) = bp(8, b2) + ((px - bp(4, b2))*fy - (py - bp(5, b2))*fx)
         bp(6, b1) = bp(6, b1) - fx
         bp(7, b1) = bp(7, b1) - fy
         bp(8, b1) = bp(8, b1) - ((px - bp(4, b1))*fy - (py - bp(5, b1))*fx)
      end do
   end subroutine rigid_kernel_loop

   !> mohr_coulomb_rigid_kernel for the force pass on more than one thread
   !> (contact_mechanics' split_force_pass): the same contacts, but instead of
   !> adding to the blocks' sums the force and the two moments of entry i go
   !> to cf(1:4, i) = fx, fy, moment about block1, moment about block2, which
   !> contact_mechanics adds to the blocks in this loop's order. A loop of its
   !> own, not a flag of the one-thread one: the flag cost that loop 24
   !> instructions a contact.
   subroutine mohr_coulomb_rigid_split(i0, i1, gidx, block1, block2, cx, cy, cnx, cny, cgap, &
                                       clen, fn, fs, un, us, flags, ud, has_ud, bp, gap_new, props, &
                                       per_length, fracture_flag, dt, geometric, gap_tol, clemin, &
                                       beta, cf)
      integer, intent(in) :: i0, i1
      integer, intent(in) :: gidx(*)
      integer(ip), intent(in) :: block1(*), block2(*)
      real(wp), intent(in) :: cx(*), cy(*), cnx(*), cny(*), clen(*)
      real(wp), intent(inout) :: cgap(*), fn(*), fs(*), un(*), us(*), ud(*)
      logical, intent(in) :: has_ud
      integer(int8), intent(inout) :: flags(*)
      real(wp), intent(in) :: bp(8, *)
      real(wp), intent(inout) :: gap_new(*)
      type(joint_props_t), intent(in) :: props
      logical, intent(in) :: per_length, fracture_flag, geometric
      real(wp), intent(in) :: dt, gap_tol, clemin, beta
      real(wp), intent(inout) :: cf(4, *)
      integer :: i
      integer(ip) :: c, b1, b2
      real(wp) :: px, py, fx, fy
      do i = i0, i1
         c = gidx(i)
         b1 = block1(c)
         b2 = block2(c)
         px = cx(c)
         py = cy(c)
         call mohr_coulomb_rigid_contact(c, b1, b2, px, py, cnx, cny, cgap, clen, fn, fs, un, us, &
                                         flags, ud, has_ud, bp, gap_new, props, per_length, &
                                         fracture_flag, props%dilation > 0.0_wp, beta > 0.0_wp, dt, &
                                         geometric, gap_tol, clemin, beta, fx, fy)
         cf(1, i) = fx
         cf(2, i) = fy
         cf(3, i) = (px - bp(4, b1))*fy - (py - bp(5, b1))*fx
         cf(4, i) = (px - bp(4, b2))*fy - (py - bp(5, b2))*fx
      end do
   end subroutine mohr_coulomb_rigid_split

   !> Stiffnesses of the continuously-yielding joint at normal stress `sn`
   !> (Eqs. 10, 12: k = a sigma_n^e, a = JKN / JKS, e = JEN / JES; e = 0 is a
   !> constant stiffness). sigma_n^e is 0 at sigma_n = 0 for e > 0, so a
   !> closing joint could never take load: at sigma_n <= 0 the factor a is
   !> used (docs/mechanics.md).
   pure subroutine yielding_stiffness(props, sn, kn, ks)
      type(joint_props_t), intent(in) :: props
      real(wp), intent(in) :: sn
      real(wp), intent(out) :: kn, ks
      kn = props%kn
      ks = props%ks
      if (sn <= 0.0_wp) return
      if (props%en /= 0.0_wp) kn = props%kn*sn**props%en
      if (props%es /= 0.0_wp) ks = props%ks*sn**props%es
   end subroutine yielding_stiffness

   !> Shear stress ratio of one contact (HISTORY SRAT, used by Appendix B,
   !> Application D; not in Section 4.5's list): |shear force| over the
   !> shear strength the contact's law has now, the quantity the law caps the
   !> shear at, so 1 means slipping and 0.5 half-way there.
   !>   JCONS 1: CCOH + Fn CFRIC (point contact: forces);
   !>   JCONS 2, 5: (JCOH L + Fn JFRIC), L the effective length (at least
   !>     CLEMIN); a fractured JCONS 5 contact has lost its cohesion;
   !>   JCONS 3: tau_m = sigma_n tan(phi_eff) (Eq. 14, E-4), the bounding
   !>     strength the shear tends to; phi_eff its current value (JIF before
   !>     the first step).
   !> A contact with no strength (open, or cohesionless and unloaded) reads 1:
   !> it cannot take any shear, which is the state the ratio flags.
   pure function joint_shear_ratio(props, jcons, fn, fs, length, phi_eff, flags) result(ratio)
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: jcons
      integer(int8), intent(in) :: flags
      real(wp), intent(in) :: fn, fs, length, phi_eff
      real(wp) :: ratio, strength, phi
      select case (jcons)
      case (1)
         strength = props%cohesion + fn*props%friction
      case (3)
         phi = phi_eff
         if (phi <= 0.0_wp) phi = props%initial_friction
         if (phi <= 0.0_wp) phi = atan(props%friction)
         strength = fn*tan(phi)
      case default
         if (jcons == 5 .and. iand(flags, state_fractured) /= 0) then
            strength = fn*props%friction
         else
            strength = props%cohesion*length + fn*props%friction
         end if
      end select
      if (iand(flags, state_tension) /= 0) strength = 0.0_wp
      if (strength > 0.0_wp) then
         ratio = abs(fs)/strength
      else
         ratio = 1.0_wp
      end if
   end function joint_shear_ratio

   !> True for a law whose stiffness depends on its state: JCONS 3 with JEN
   !> or JES non-zero (the time step then follows the contacts' current
   !> stiffness, contact_mechanics).
   pure logical function state_dependent(props, jcons)
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: jcons
      state_dependent = jcons == 3 .and. (props%en /= 0.0_wp .or. props%es /= 0.0_wp)
   end function state_dependent

   !> Continuously-yielding joint: manual Section 3.3, Eqs. 10-18, in the
   !> order of the algorithm of Appendix B, Application E (Eqs. E-1 to E-12).
   !> Per contact, with sigma_n compression positive and u_n opening positive:
   !>   k_n from sigma_n; sigma_n -= k_n du_n (Eq. 10, E-2); sigma_n <= 0:
   !>   the joint is open (no tensile strength), forces and r are zeroed;
   !>   k_s from the new sigma_n (Eq. 12, E-3);
   !>   tau_m = sigma_n tan(phi_eff) sign(du_s) (Eq. 14);
   !>   reversal (sign(du_s) /= sign(du_s_old)): r = tau / tau_m, at most 0.75
   !>   (Section 3.3 text; r has the sign of tau / tau_m, so F = 1 right after
   !>   any reversal);
   !>   F = (1 - tau / tau_m) / (1 - r), at most 1 (Eq. 13; see below);
   !>   tau += F k_s du_s (Eq. 11), stopping at tau_m where a large step
   !>   would cross it (the equation only tends to tau_m);
   !>   du_s^p = max(0, 1 - F) |du_s| (Eq. 16 as E-10: plastic displacement
   !>   only grows); phi_eff = phi + (phi_eff - phi) exp(-du_s^p / R) (Eq. 17
   !>   over the step, the exact integral of Eq. 15); R = 0 (JR not given):
   !>   phi_eff stays at its initial value;
   !>   i = max(0, atan(|tau| / sigma_n) - phi) (Eq. 18, E-11);
   !>   sigma_n += k_n |du_s| tan(i) (E-12): the joint dilates by
   !>   |du_s| tan(i), which under a fixed normal displacement raises sigma_n
   !>   and under a constant normal stress opens the joint by that much.
   !> F is capped at 1: with r > 0 kept from a reversal, a rise of sigma_n
   !> (tau_m up) would otherwise make the joint stiffer than elastic, up to
   !> 4 k_s for r = 0.75 (the manual warns of this load path, Section 3.3,
   !> last paragraph); the cap keeps k_s the largest shear stiffness, which
   !> the time step assumes.
   !> With JEN or JES non-zero, `kmax` is raised to the largest stiffness (k_n
   !> or k_s times the length) an updated contact will use at its next step
   !> (the engine's time step follows it).
   subroutine yielding_update(this, props, idx, n, length, dun, dus, state, kmax)
      class(joint_yielding_t), intent(in) :: this
      type(joint_props_t), intent(in) :: props
      integer, intent(in) :: n
      integer, intent(in) :: idx(n)
      real(wp), intent(in) :: length(n), dun(n), dus(n)
      type(joint_state_t), intent(inout) :: state
      real(wp), intent(inout) :: kmax
      integer :: i, c
      real(wp) :: sn, ss, ss_new, kn, ks, kn_next, ks_next, tau_m, f, r, phi, phi0, dusp, l, dil
      real(wp), parameter :: r_max = 0.75_wp
      logical :: by_state
      if (this%jcons /= 3) return
      ! the JCONS 3 fields exist once a group takes this law
      ! (contact_groups_build, joint_state_jcons3); this is the fallback for a
      ! caller that hands the law a state of its own
      if (.not. allocated(state%phi_eff)) allocate (state%phi_eff(size(state%fn)), &
         state%reversal(size(state%fn)), state%dus_old(size(state%fn)), source=0.0_wp)
      if (.not. allocated(state%ud)) allocate (state%ud(size(state%fn)), source=0.0_wp)
      by_state = state_dependent(props, 3)
      phi = atan(props%friction)
      phi0 = phi
      if (props%initial_friction > 0.0_wp) phi0 = props%initial_friction
      do i = 1, n
         c = idx(i)
         l = max(length(i), tiny(1.0_wp))
         sn = state%fn(c)/l                          ! compression positive
         ss = state%fs(c)/l
         if (state%phi_eff(c) <= 0.0_wp) state%phi_eff(c) = phi0
         call yielding_stiffness(props, sn, kn, ks)
         state%un(c) = state%un(c) + dun(i)
         state%us(c) = state%us(c) + dus(i)
         sn = sn - kn*dun(i)                          ! Eq. 10
         if (sn <= 0.0_wp) then                       ! open: no tensile strength
            state%fn(c) = 0.0_wp
            state%fs(c) = 0.0_wp
            state%flags(c) = state_tension
            state%reversal(c) = 0.0_wp
            state%dus_old(c) = 0.0_wp
            if (by_state) kmax = max(kmax, max(props%kn, props%ks)*l)
            cycle
         end if
         state%flags(c) = 0
         if (dus(i) /= 0.0_wp) then
            call yielding_stiffness(props, sn, kn_next, ks)   ! Eq. 12 at the new sigma_n (E-3)
            tau_m = sn*tan(state%phi_eff(c))*sign(1.0_wp, dus(i))   ! Eq. 14
            r = state%reversal(c)
            if (state%dus_old(c) /= 0.0_wp .and. &
                sign(1.0_wp, dus(i)) /= sign(1.0_wp, state%dus_old(c))) then
               r = 0.0_wp                                   ! load reversal
               if (tau_m /= 0.0_wp) r = min(ss/tau_m, r_max)
            end if
            if (tau_m /= 0.0_wp) then
               ! Eq. 13; F < 0 above the bounding strength brings the stress
               ! down to it. After a sudden drop of sigma_n, tau / tau_m can be
               ! large and F = 1 - tau / tau_m a negative stiffness far beyond
               ! ks, which the explicit step cannot follow: F >= -1 keeps
               ! that stiffness within the |ks| the time step allows for
               f = max(min((1.0_wp - ss/tau_m)/(1.0_wp - r), 1.0_wp), -1.0_wp)
            else
               f = 0.0_wp                                   ! no strength: no shear stress
               ss = 0.0_wp
            end if
            ss_new = ss + f*ks*dus(i)                       ! Eq. 11
            ! Eq. 11 makes tau tend to tau_m from either side; a step with
            ! k_s |du_s| above tau_m (1 - r) would carry it across. In a fast
            ! slip (a brittle joint softening faster than the blocks unload)
            ! that step dropped tau far below tau_m, the blocks then shot
            ! past each other and E-12's dilation, k_n |du_s| tan(i), pumped
            ! energy in. tau stops at tau_m instead (a step too small to
            ! cross is unchanged).
            if (tau_m /= 0.0_wp) then
               if ((ss - tau_m)*(ss_new - tau_m) < 0.0_wp) ss_new = tau_m
            end if
            ss = ss_new
            dusp = max(0.0_wp, 1.0_wp - f)*abs(dus(i))      ! Eq. 16, E-10
            if (props%roughness > 0.0_wp) state%phi_eff(c) = phi + &
               (state%phi_eff(c) - phi)*exp(-dusp/props%roughness)   ! Eqs. 15, 17
            dil = max(0.0_wp, atan(abs(ss)/sn) - phi)       ! Eq. 18, E-11
            sn = sn + kn*abs(dus(i))*tan(dil)               ! E-12
            state%ud(c) = state%ud(c) + abs(dus(i))*tan(dil)   ! the opening ridden up
            state%reversal(c) = r
            state%dus_old(c) = dus(i)
            if (f < 1.0_wp) state%flags(c) = state_slip
         end if
         if (by_state) then
            call yielding_stiffness(props, sn, kn_next, ks_next)
            kmax = max(kmax, kn_next*l, ks_next*l)
         end if
         state%fn(c) = sn*l
         state%fs(c) = ss*l
      end do
   end subroutine yielding_update

end module contact_joint_law
