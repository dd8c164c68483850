!> Contact forces of one explicit step (manual Sections 3.3 and 3.5): for
!> every live contact, the relative displacement increment from the block
!> motion, the joint law (one call per group of contacts sharing a law and a
!> joint material, the loop over the group inside the kernel), and the force
!> and moment sums of the two blocks.
!>
!> Normal displacement increment: the change of the geometric gap of the
!> rounded surfaces (contact_kinematics), so that a contact made while
!> still open gets no force until the surfaces touch, and a contact that
!> has opened with no force left stays force-free until it closes again.
!> The gap that counts is the geometric gap less the dilation the joint has
!> ridden up (state%ud, recorded by the laws: the asperities fill it):
!>    open (fn = 0 and gap - ud > gap_tol): dun = min(gap_new - ud, 0)
!>    otherwise                              dun = gap_new - gap_old
!> The law gets that dun; the normal displacement un (PRINT CONTACT DISP,
!> HISTORY NDIS, the fluid aperture a0 + un of Eq. 55) takes the whole gap
!> change, open or closed: with the law's dun alone, a contact that opened
!> kept the opening of the step it opened in and lost the closing travel
!> of the step it closed, and each open-close of a chattering contact left
!> that difference in un (the trailing contact of a zoned block sliding
!> down a slope: un 6.4e-5 m open where the gap was 1.9e-6 m closed, after
!> 3.6 m of slide; verification.closed_forms).
!> A contact open before and after the step (fn = 0, both gaps - ud >
!> gap_tol) takes no shear increment and keeps fs = 0: without this, a joint
!> with JCOH > 0 carried up to its cohesion across an open gap (a block at a
!> pit crest hung on a 1 mm open joint), and a dilatant joint (JDIL > 0)
!> made a normal force out of nothing from the shear of an open contact,
!> kn tan(psi) |du_s| a step, which pushed blocks apart across a gap of any
!> size and sent a block sliding on a dilatant joint flying
!> (verification.closed_forms, dilatant sliding).
!> Shear displacement increment: relative velocity of the contact point
!> along the tangent t = (-ny, nx) times dt (velocities at t + dt/2).
!> Force on block2 = fn n - fs t; on block1 the opposite.
!>
!> Moment balance of the pair: a rigid side takes the force at the contact
!> point, a deformable (FDEF) side at the point its gridpoints interpolate
!> (the corner gridpoint, or the point on the edge). Where these differ (by
!> the gap or overlap, along the normal) the pair of forces has the moment
!> (p2 - p1) x F, of order overlap times shear force, which no other force
!> balances: it turns a model held by boundary stresses alone at a steady
!> angular acceleration (verification/E/README.md). That moment is given
!> back as a couple: into the moment sum of a rigid side (block 2 if both
!> are rigid), else, both sides zoned, as forces -/+ k (-ey, ex) at the two
!> gridpoints of block 2's contact edge (or of the edge that starts at its
!> contact corner), e = edge vector, k |e|^2 = -moment. Where side 2's point
!> is an end of its edge (w = 0 or 1: a corner filling a re-entrant gridpoint
!> lies beyond both edges that meet there, and contact_side picks either from
!> step to step by round-off) the couple goes to the edge that starts at that
!> gridpoint, as for a corner: on the edge picked, a couple of 1.5e3 N m
!> jumped between two edges every few steps and held a zoned jointed model
!> loaded by BOUNDARY STRESS alone at an unbalanced force of 3e3 N for ever
!> (stability.bstress_joint_mouth). The force sums are
!> unchanged. At a rigid block's rounded corner the two points differ by
!> about a rounding length along the joint, and the couple (rounding times
!> the normal force) given to a zoned block's two gridpoints pushed them
!> 4e-5 m in a model held by its in-situ stress (stability.insitu_mixed_rigid);
!> a rigid block takes it whole.
module contact_mechanics
   use core_kinds, only: wp, ip, l1
   use model_properties, only: prop_ccohesion, prop_cdilation, prop_cfriction, prop_ctensile, &
                                 prop_jcoh, prop_jdil, prop_jen, prop_jes, prop_jfric, &
                                 prop_jif, prop_jkn, prop_jks, prop_jr, prop_jtensile, &
                                 prop_kn, prop_ks
   use core_error, only: error_t, set_error
   use core_arrays, only: list_capacity
   use model_geometry, only: geometry_t, contact_side_gridpoints, contact_side, joint_state_jcons3, &
                             joint_state_ud, joint_state_value
   use model_materials, only: material_table_t
   use contact_joint_law, only: joint_law_t, joint_props_t, joint_law_create, state_slip, &
                                state_dependent, yielding_stiffness, joint_mohr_coulomb_t, &
                                mohr_coulomb_rigid_kernel, mohr_coulomb_rigid_split
   use contact_kinematics, only: contact_geometry_all, edge_frames_compute
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: contact_work_t, contact_work_setup, contact_groups_build
   public :: contact_geometry_pass, contact_force_pass, joint_props_of, contact_stiffness_max
   public :: contact_state_stiffness

   !> Fewer live contacts than this run on one thread whatever OMP_NUM_THREADS
   !> says (the threads' start and join would cost more than they save).
   !> Without OMP_NUM_THREADS in the environment the contact passes run on one
   !> thread (contact_work_setup), as the zone passes do.
   integer(ip), parameter :: thread_min_contacts = 4000

   type :: law_holder_t
      class(joint_law_t), allocatable :: law
   end type law_holder_t

   !> Workspace of the contact phase, kept for the length of one CYCLE
   !> command; arrays grow only when contacts are made (at scans).
   type :: contact_work_t
      integer(ip) :: cap = 0
      !> capacity of the arrays only the general force pass uses (glen, gdun,
      !> gdus, sga, sgb, sw): 0 while every group takes rigid_group_pass
      integer(ip) :: cap_general = 0
      real(wp), allocatable :: gap_new(:)
      !> the step's scratch (issue 23: one array for two that are never in use
      !> together): the edge frames of the corners at the current positions,
      !> frame(4, corners), from edge_frames_compute to the end of the
      !> geometry pass (contact_geometry_pass), then the packed blocks,
      !> bpack(8, blocks), from block_pack to block_unpack in the force pass.
      !> Each is written whole before it is read (the frames of every corner
      !> id, the pack of every block), so neither reads the other's values.
      !> Sized to the larger, it grows only when corners or blocks are made.
      real(wp), allocatable :: scratch(:)
      ! groups: contacts sharing (jcons, jmat), stored contiguously
      integer :: ngroup = 0
      integer, allocatable :: gjcons(:), gjmat(:), gstart(:)
      integer, allocatable :: gidx(:)
      type(joint_props_t), allocatable :: gprops(:)
      real(wp), allocatable :: glen(:), gdun(:), gdus(:)
      ! gridpoints and weights of the two sides of a contact with an FDEF
      ! block (contact_side_gridpoints), found once per step for velocity and force
      integer(ip), allocatable :: sga(:, :), sgb(:, :)   !< (2, cap): side 1, side 2
      real(wp), allocatable :: sw(:, :)
      !> contact touches an excavated block (FDEF, CONS 0): no force, no
      !> overlap check (see contact_groups_build)
      logical(l1), allocatable :: void(:)
      type(law_holder_t) :: laws(5)          !< by JCONS number (1, 2, 3, 5)
      !> no live block is FDEF or SDEF (contact_groups_build): the force pass
      !> takes its rigid-block loop (rigid_group_pass)
      logical :: rigid_only = .false.
      real(wp) :: clemin = 0.0_wp            !< minimum contact length in use
      real(wp) :: beta = 0.0_wp              !< stiffness-proportional damping [s]
      real(wp) :: gap_tol = 0.0_wp           !< below this a gap counts as closed
      real(wp) :: switch_tol = 0.0_wp        !< hysteresis of corner/edge switches
      !> largest stiffness [force/length] of the contacts whose law's stiffness
      !> depends on their state (JCONS 3 with JEN or JES), as the last force
      !> pass left them; 0 when there are none
      real(wp) :: kstate = 0.0_wp
      !> the value of kstate the current time step was computed with
      real(wp) :: kstate_dt = 0.0_wp
      !> threads of the contact passes (1 without OpenMP or OMP_NUM_THREADS)
      integer :: nthreads = 1
      !> the force pass runs split (contact_groups_build): more than one thread,
      !> enough contacts, every group takes rigid_group_pass. Each contact's
      !> force and moments go to cf(1:4, i) (i its place in gidx), and every
      !> block then adds its contacts' terms in the one-thread order:
      !> blist(bptr(b) : bptr(b + 1) - 1) = +i where b is block2 of entry i,
      !> -i where it is block1, i increasing. Same bits at any thread count.
      logical :: split = .false.
      real(wp), allocatable :: cf(:, :)
      integer(ip), allocatable :: bptr(:), blist(:)
   end type contact_work_t

contains

   !> Properties of joint material `jmat` for the law `jcons` (Section 4.5
   !> PROPERTY: KN KS CCOH CFRIC CTENS CDIL for JCONS 1, JKN JKS JCOH JFRIC
   !> JTENS JDIL for 2 and 5, JKN JKS JEN JES JFRIC JIF JR for 3).
   pure function joint_props_of(mats, jmat, jcons) result(p)
      type(material_table_t), intent(in) :: mats
      integer, intent(in) :: jmat, jcons
      type(joint_props_t) :: p
      if (jcons == 1) then
         p%kn = mats%get(jmat, prop_kn)
         p%ks = mats%get(jmat, prop_ks)
         p%cohesion = mats%get(jmat, prop_ccohesion)
         p%friction = mats%get(jmat, prop_cfriction)
         p%tension = mats%get(jmat, prop_ctensile)
         p%dilation = mats%get(jmat, prop_cdilation)
      else
         p%kn = mats%get(jmat, prop_jkn)
         p%ks = mats%get(jmat, prop_jks)
         p%cohesion = mats%get(jmat, prop_jcoh)
         p%friction = mats%get(jmat, prop_jfric)
         p%tension = mats%get(jmat, prop_jtensile)
         p%dilation = mats%get(jmat, prop_jdil)
         p%en = mats%get(jmat, prop_jen)
         p%es = mats%get(jmat, prop_jes)
         p%initial_friction = mats%get(jmat, prop_jif)
         p%roughness = mats%get(jmat, prop_jr)
      end if
   end function joint_props_of

   !> Create the laws and size the workspace.
   subroutine contact_work_setup(work, geo, error)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      integer, parameter :: known(4) = [1, 2, 3, 5]
      do j = 1, 4
         if (.not. allocated(work%laws(known(j))%law)) then
            call joint_law_create(known(j), work%laws(known(j))%law, error)
            if (allocated(error)) return
         end if
      end do
      call ensure(work, max(16_ip, geo%contacts%n))
      work%gap_tol = 10.0_wp*geo%tol
      ! threads only when asked for (OMP_NUM_THREADS set), as the zone passes
      work%nthreads = 1
      call get_environment_variable('OMP_NUM_THREADS', status=j)
      if (j == 0) then
         !$ work%nthreads = omp_get_max_threads()
      end if
   end subroutine contact_work_setup

   subroutine ensure(work, n)
      type(contact_work_t), intent(inout) :: work
      integer(ip), intent(in) :: n
      integer(ip) :: m
      if (n <= work%cap) return
      ! a quarter more, as the contact list grows (list_capacity): doubling
      ! left up to half of these 16 bytes a contact (72 with the general
      ! pass's arrays) unused after a scan that made a few contacts
      m = list_capacity(work%cap, n)
      if (allocated(work%gap_new)) deallocate (work%gap_new, work%gidx, work%void)
      allocate (work%gap_new(m), work%gidx(m), work%void(m))
      work%cap = m
      ! the general pass's arrays follow the capacity once they are in use
      if (work%cap_general > 0) call ensure_general(work)
   end subroutine ensure

   !> The arrays of the general force pass at the workspace's capacity. A model
   !> of rigid blocks whose groups all take rigid_group_pass never allocates
   !> them (56 bytes a contact).
   subroutine ensure_general(work)
      type(contact_work_t), intent(inout) :: work
      integer(ip) :: m
      m = work%cap
      if (m <= work%cap_general) return
      if (allocated(work%glen)) deallocate (work%glen, work%gdun, work%gdus, work%sga, work%sgb, work%sw)
      allocate (work%glen(m), work%gdun(m), work%gdus(m), work%sga(2, m), work%sgb(2, m), work%sw(2, m))
      work%cap_general = m
   end subroutine ensure_general

   !> Group live contacts by (JCONS, JMAT); check every group has a law and
   !> a normal stiffness; effective minimum length CLEMIN (`clemin_set` > 0
   !> as given by SET CLEMIN, else 1/10 of the average length of the contacts
   !> that have one, remembered in `clemin_auto` for when none has, e.g. a
   !> block pivoting on one corner; before any contact had a length, 1/100
   !> of the mean block size).
   subroutine contact_groups_build(work, geo, mats, clemin_set, clemin_auto, error)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(inout) :: geo
      type(material_table_t), intent(in) :: mats
      real(wp), intent(in) :: clemin_set
      real(wp), intent(inout) :: clemin_auto
      type(error_t), allocatable, intent(out) :: error
      integer :: g, ng
      integer(ip) :: c, nlen
      integer, allocatable :: gcount(:), gj(:), gm(:), fill(:), cgroup(:)
      real(wp) :: lsum
      character(len=160) :: msg
      call ensure(work, geo%contacts%n)
      allocate (gj(8), gm(8), gcount(8), cgroup(max(1_ip, geo%contacts%n)))
      ng = 0
      lsum = 0.0_wp
      nlen = 0
      do c = 1, geo%contacts%n
         cgroup(c) = 0
         work%void(c) = .false._l1
         if (.not. geo%contacts%live(c)) cycle
         if (null_block(geo, geo%contacts%block1(c)) .or. null_block(geo, geo%contacts%block2(c))) then
            ! excavated material (CONS 0 zones) carries no contact force:
            ! its gridpoints would otherwise stay wedged in the corners of
            ! the opening and prop it
            work%void(c) = .true._l1
            geo%contacts%state%fn(c) = 0.0_wp
            geo%contacts%state%fs(c) = 0.0_wp
            cycle
         end if
         if (geo%contacts%length(c) > 0.0_wp) then
            lsum = lsum + geo%contacts%length(c)
            nlen = nlen + 1
         end if
         do g = 1, ng
            if (gj(g) == geo%contacts%jcons(c) .and. gm(g) == geo%contacts%jmat(c)) exit
         end do
         if (g > ng) then
            if (ng == size(gj)) then
               gj = [gj, gj]; gm = [gm, gm]; gcount = [gcount, gcount]
            end if
            ng = ng + 1
            g = ng
            gj(g) = geo%contacts%jcons(c)
            gm(g) = geo%contacts%jmat(c)
            gcount(g) = 0
         end if
         cgroup(c) = g
         gcount(g) = gcount(g) + 1
      end do
      if (nlen > 0) then
         clemin_auto = 0.1_wp*lsum/real(nlen, wp)
      else if (clemin_auto <= 0.0_wp) then
         call mean_block_size(geo, clemin_auto)
         clemin_auto = 0.01_wp*clemin_auto
      end if
      work%clemin = clemin_set
      if (work%clemin <= 0.0_wp) work%clemin = clemin_auto
      if (allocated(work%gjcons)) deallocate (work%gjcons, work%gjmat, work%gstart, work%gprops)
      allocate (work%gjcons(ng), work%gjmat(ng), work%gstart(ng + 1), work%gprops(ng))
      work%ngroup = ng
      work%gstart(1) = 1
      do g = 1, ng
         work%gjcons(g) = gj(g)
         work%gjmat(g) = gm(g)
         work%gstart(g + 1) = work%gstart(g) + gcount(g)
         if (gj(g) < 1 .or. gj(g) > 5) then
            write (msg, '(a,i0,a)') 'CYCLE: contacts have joint constitutive number JCONS ', gj(g), &
               '; known: 1, 2, 3, 5'
            call set_error(error, trim(msg))
            return
         end if
         if (.not. allocated(work%laws(gj(g))%law)) then
            write (msg, '(a,i0,a)') 'CYCLE: contacts have joint constitutive number JCONS ', gj(g), &
               '; known: 1, 2, 3, 5'
            call set_error(error, trim(msg))
            return
         end if
         if (gj(g) == 3) call joint_state_jcons3(geo%contacts)
         work%gprops(g) = joint_props_of(mats, gm(g), gj(g))
         ! the dilation ridden up only where a law can change it
         if (gj(g) == 3 .or. work%gprops(g)%dilation > 0.0_wp) call joint_state_ud(geo%contacts)
         if (work%gprops(g)%kn <= 0.0_wp .or. work%gprops(g)%ks < 0.0_wp) then
            if (gj(g) == 1) then
               write (msg, '(a,i0,a)') 'CYCLE: joint material ', gm(g), &
                  ' has no normal stiffness: give PROPERTY JMAT=n KN=.. KS=.. (JCONS 1)'
            else
               write (msg, '(a,i0,a)') 'CYCLE: joint material ', gm(g), &
                  ' has no normal stiffness: give PROPERTY JMAT=n JKN=.. JKS=..'
            end if
            call set_error(error, trim(msg))
            return
         end if
      end do
      work%rigid_only = .true.
      do c = 1, geo%blocks%n
         if (.not. geo%blocks%live(c)) cycle
         if (geo%blocks%fdef(c) .or. geo%blocks%sdef(c)) then
            work%rigid_only = .false.
            exit
         end if
      end do
      ! a group that will not take rigid_group_pass needs the general arrays
      do g = 1, ng
         if (.not. rigid_pass_of(work, g)) then
            call ensure_general(work)
            exit
         end if
      end do
      allocate (fill(ng))
      fill = work%gstart(1:ng)
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         g = cgroup(c)
         if (g == 0) cycle
         work%gidx(fill(g)) = int(c)
         fill(g) = fill(g) + 1
      end do
      call split_lists(work, geo)
   end subroutine contact_groups_build

   !> The lists of the split force pass (contact_work_t%split): for every block
   !> the entries of gidx it takes a force from, in increasing order, which is
   !> the order of the one-thread loop (group by group, gidx order).
   subroutine split_lists(work, geo)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      integer :: g
      integer(ip) :: i, ntot, b, c
      integer(ip), allocatable :: fill(:)
      work%split = .false.
      if (allocated(work%cf)) deallocate (work%cf, work%bptr, work%blist)
      if (work%nthreads <= 1 .or. work%ngroup == 0) return
      ntot = work%gstart(work%ngroup + 1) - 1
      if (ntot < thread_min_contacts) return
      do g = 1, work%ngroup
         if (.not. rigid_pass_of(work, g)) return
      end do
      work%split = .true.
      allocate (work%cf(4, ntot), work%bptr(geo%blocks%n + 1), work%blist(2*ntot))
      work%bptr = 0
      do i = 1, ntot
         c = work%gidx(i)
         b = geo%contacts%block1(c)
         work%bptr(b + 1) = work%bptr(b + 1) + 1
         b = geo%contacts%block2(c)
         work%bptr(b + 1) = work%bptr(b + 1) + 1
      end do
      work%bptr(1) = 1
      do b = 1, geo%blocks%n
         work%bptr(b + 1) = work%bptr(b + 1) + work%bptr(b)
      end do
      allocate (fill(geo%blocks%n))
      fill = work%bptr(1:geo%blocks%n)
      do i = 1, ntot
         c = work%gidx(i)
         b = geo%contacts%block1(c)
         work%blist(fill(b)) = -i
         fill(b) = fill(b) + 1
         b = geo%contacts%block2(c)
         work%blist(fill(b)) = i
         fill(b) = fill(b) + 1
      end do
   end subroutine split_lists

   !> Group `g` of the force pass runs rigid_group_pass: no live block is
   !> FDEF or SDEF and the group's law is Mohr-Coulomb (JCONS 1, 2, 5).
   logical function rigid_pass_of(work, g) result(rigid)
      type(contact_work_t), intent(in) :: work
      integer, intent(in) :: g
      rigid = .false.
      if (.not. work%rigid_only) return
      select type (law => work%laws(work%gjcons(g))%law)
      type is (joint_mohr_coulomb_t)
         rigid = .true.
      end select
   end function rigid_pass_of

   !> A fully-deformable block of the null model (CONS 0): excavated.
   pure logical function null_block(geo, b)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      null_block = geo%blocks%fdef(b) .and. geo%blocks%cons(b) == 0
   end function null_block

   subroutine mean_block_size(geo, size_mean)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(out) :: size_mean
      integer(ip) :: b, n
      size_mean = 0.0_wp
      n = 0
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         size_mean = size_mean + sqrt(geo%blocks%area(b))
         n = n + 1
      end do
      if (n > 0) size_mean = size_mean/real(n, wp)
   end subroutine mean_block_size

   !> Largest contact stiffness max(kn, ks) [force/length] over live
   !> contacts, with lengths as the laws use them; a law whose stiffness
   !> depends on its state (state_dependent) counts each contact at its
   !> current normal stress (Eqs. 10, 12), and never below the factors JKN,
   !> JKS it starts from at sigma_n = 0.
   pure real(wp) function contact_stiffness_max(work, geo) result(kmax)
      type(contact_work_t), intent(in) :: work
      type(geometry_t), intent(in) :: geo
      integer :: g, i
      integer(ip) :: c
      real(wp) :: l, k, kn, ks
      logical :: by_state
      kmax = 0.0_wp
      do g = 1, work%ngroup
         k = max(work%gprops(g)%kn, work%gprops(g)%ks)
         by_state = state_dependent(work%gprops(g), work%gjcons(g))
         if (work%gjcons(g) == 1) then
            kmax = max(kmax, k)
         else
            do i = work%gstart(g), work%gstart(g + 1) - 1
               c = work%gidx(i)
               l = max(geo%contacts%length(c), work%clemin)
               if (by_state) then
                  call yielding_stiffness(work%gprops(g), geo%contacts%state%fn(c)/l, kn, ks)
                  kmax = max(kmax, k*l, kn*l, ks*l)
               else
                  kmax = max(kmax, k*l)
               end if
            end do
         end if
      end do
   end function contact_stiffness_max

   !> Largest current stiffness of the contacts of state-dependent laws
   !> (state_dependent): `kforce` max(kn, ks) times the length [force/length],
   !> as the laws report it in `work%kstate` after a force pass, and `kunit`
   !> max(kn, ks) per unit length [stress/length]; both 0 when there are none.
   pure subroutine contact_state_stiffness(work, geo, kforce, kunit)
      type(contact_work_t), intent(in) :: work
      type(geometry_t), intent(in) :: geo
      real(wp), intent(out) :: kforce, kunit
      integer :: g, i
      integer(ip) :: c
      real(wp) :: l, kn, ks
      kforce = 0.0_wp
      kunit = 0.0_wp
      do g = 1, work%ngroup
         if (.not. state_dependent(work%gprops(g), work%gjcons(g))) cycle
         do i = work%gstart(g), work%gstart(g + 1) - 1
            c = work%gidx(i)
            l = max(geo%contacts%length(c), work%clemin)
            call yielding_stiffness(work%gprops(g), geo%contacts%state%fn(c)/l, kn, ks)
            kunit = max(kunit, kn, ks)
            kforce = max(kforce, kn*l, ks*l)
         end do
      end do
   end subroutine contact_state_stiffness

   !> Gap, normal and point of every live contact at the current positions
   !> (gaps into work%gap_new). Returns the contact with the largest overlap
   !> beyond `ovtol` in `bad` (0 if none); its own tolerance may be larger
   !> (contact_kinematics' overlap_judge, run by the caller when bad > 0).
   subroutine contact_geometry_pass(work, geo, ovtol, bad)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: ovtol
      integer(ip), intent(out) :: bad
      bad = 0
      if (geo%contacts%n == 0) return
      call scratch_ensure(work, geo)
      call edge_frames_compute(geo, work%scratch, work%nthreads)
      call contact_geometry_all(geo, work%switch_tol, work%scratch, work%void, ovtol, work%gap_new, bad, &
                                merge(work%nthreads, 1, geo%contacts%n >= thread_min_contacts))
   end subroutine contact_geometry_pass

   !> Displacement increments, joint laws, force sums into the blocks.
   !> `geometric` false (SET UPCON n > 1, between updates): the normal
   !> increment comes from the relative velocity along the last normal.
   subroutine contact_force_pass(work, geo, dt, geometric)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: dt
      logical, intent(in) :: geometric
      integer :: g, i, n, i0
      integer(ip) :: c, b1, b2
      real(wp) :: px, py, v1x, v1y, v2x, v2y, rvx, rvy, nx, ny, tx, ty, vn, vs
      real(wp) :: gold, gnew, fx, fy, kn, ks, l, w, udc
      real(wp) :: x1, y1, x2, y2, pair_moment
      integer(ip) :: ga, gb, corner, edge, other
      logical :: packed
      work%kstate = 0.0_wp
      if (work%split) then
         call split_force_pass(work, geo, dt, geometric)
         return
      end if
      packed = .false.    ! the blocks' force sums are in the pack (work%scratch)
      associate (ct => geo%contacts, bl => geo%blocks, gp => geo%gridpoints)
         do g = 1, work%ngroup
            i0 = work%gstart(g)
            n = work%gstart(g + 1) - i0
            if (rigid_pass_of(work, g)) then
               if (.not. packed) call block_pack(work, geo)
               packed = .true.
               select type (law => work%laws(work%gjcons(g))%law)
               type is (joint_mohr_coulomb_t)
                  call rigid_group_pass(work, geo, g, law%per_length, law%fracture_flag, dt, &
                                        geometric)
               end select
               cycle
            end if
            if (packed) call block_unpack(work, geo)
            packed = .false.
            do i = i0, i0 + n - 1
               c = work%gidx(i)
               b1 = ct%block1(c)
               b2 = ct%block2(c)
               px = ct%x(c)
               py = ct%y(c)
               nx = ct%nx(c)
               ny = ct%ny(c)
               call side_velocity(work, geo, i, c, 1, b1, px, py, v1x, v1y)
               call side_velocity(work, geo, i, c, 2, b2, px, py, v2x, v2y)
               rvx = v2x - v1x
               rvy = v2y - v1y
               vs = -rvx*ny + rvy*nx
               work%gdus(i) = vs*dt
               gold = ct%gap(c)
               if (geometric) then
                  gnew = work%gap_new(c)
               else
                  gnew = gold + (rvx*nx + rvy*ny)*dt
                  work%gap_new(c) = gnew
               end if
               udc = joint_state_value(ct%state%ud, c)
               if (ct%state%fn(c) == 0.0_wp .and. gold - udc > work%gap_tol) then
                  work%gdun(i) = min(gnew - udc, 0.0_wp)
                  if (gnew - udc > work%gap_tol) then
                     ! still open: the surfaces do not touch, so the contact
                     ! carries no shear either (no cohesion across the gap)
                     work%gdus(i) = 0.0_wp
                     ct%state%fs(c) = 0.0_wp
                  end if
               else
                  work%gdun(i) = gnew - gold
               end if
               work%glen(i) = max(ct%length(c), work%clemin)
            end do
            call work%laws(work%gjcons(g))%law%update(work%gprops(g), work%gidx(i0:i0 + n - 1), n, &
                                                      work%glen(i0:i0 + n - 1), &
                                                      work%gdun(i0:i0 + n - 1), &
                                                      work%gdus(i0:i0 + n - 1), ct%state, &
                                                      work%kstate)
            ! force sums
            kn = work%gprops(g)%kn
            ks = work%gprops(g)%ks
            do i = i0, i0 + n - 1
               c = work%gidx(i)
               ! un follows the gap also while open (module header); an
               ! exact zero for a closed contact
               ct%state%un(c) = ct%state%un(c) + ((work%gap_new(c) - ct%gap(c)) - work%gdun(i))
               ct%gap(c) = work%gap_new(c)
               nx = ct%nx(c)
               ny = ct%ny(c)
               tx = -ny
               ty = nx
               fx = ct%state%fn(c)*nx - ct%state%fs(c)*tx
               fy = ct%state%fn(c)*ny - ct%state%fs(c)*ty
               if (work%beta > 0.0_wp .and. ct%state%fn(c) > 0.0_wp) then
                  ! stiffness-proportional dashpots (Section 3.6); the shear
                  ! dashpot is off while the contact slides
                  l = 1.0_wp
                  if (work%gjcons(g) /= 1) l = work%glen(i)
                  vn = -work%gdun(i)/dt
                  vs = work%gdus(i)/dt
                  fx = fx + work%beta*kn*l*vn*nx
                  fy = fy + work%beta*kn*l*vn*ny
                  if (iand(ct%state%flags(c), state_slip) == 0) then
                     fx = fx - work%beta*ks*l*vs*tx
                     fy = fy - work%beta*ks*l*vs*ty
                  end if
               end if
               b1 = ct%block1(c)
               b2 = ct%block2(c)
               px = ct%x(c)
               py = ct%y(c)
               ! core_forces' add_shared_force / add_rigid_force written out: the
               ! hottest loop of a rigid cycle, and gfortran does not inline a
               ! call across modules (two calls per contact per step)
               if (bl%fdef(b2)) then
                  ga = work%sga(2, i); gb = work%sgb(2, i); w = work%sw(2, i)
                  gp%fx(ga) = gp%fx(ga) + (1.0_wp - w)*fx
                  gp%fy(ga) = gp%fy(ga) + (1.0_wp - w)*fy
                  gp%fx(gb) = gp%fx(gb) + w*fx
                  gp%fy(gb) = gp%fy(gb) + w*fy
               else
                  bl%fx(b2) = bl%fx(b2) + fx
                  bl%fy(b2) = bl%fy(b2) + fy
                  bl%fm(b2) = bl%fm(b2) + ((px - bl%xc(b2))*fy - (py - bl%yc(b2))*fx)
               end if
               if (bl%fdef(b1)) then
                  ga = work%sga(1, i); gb = work%sgb(1, i); w = work%sw(1, i)
                  gp%fx(ga) = gp%fx(ga) - (1.0_wp - w)*fx
                  gp%fy(ga) = gp%fy(ga) - (1.0_wp - w)*fy
                  gp%fx(gb) = gp%fx(gb) - w*fx
                  gp%fy(gb) = gp%fy(gb) - w*fy
               else
                  bl%fx(b1) = bl%fx(b1) - fx
                  bl%fy(b1) = bl%fy(b1) - fy
                  bl%fm(b1) = bl%fm(b1) - ((px - bl%xc(b1))*fy - (py - bl%yc(b1))*fx)
               end if
               ! moment balance of the pair (module header)
               if (bl%fdef(b1) .or. bl%fdef(b2)) then
                  x1 = px; y1 = py; x2 = px; y2 = py
                  if (bl%fdef(b1)) then
                     ga = work%sga(1, i); gb = work%sgb(1, i); w = work%sw(1, i)
                     x1 = (1.0_wp - w)*gp%x(ga) + w*gp%x(gb)
                     y1 = (1.0_wp - w)*gp%y(ga) + w*gp%y(gb)
                  end if
                  if (bl%fdef(b2)) then
                     ga = work%sga(2, i); gb = work%sgb(2, i); w = work%sw(2, i)
                     x2 = (1.0_wp - w)*gp%x(ga) + w*gp%x(gb)
                     y2 = (1.0_wp - w)*gp%y(ga) + w*gp%y(gb)
                  end if
                  pair_moment = (x2 - x1)*fy - (y2 - y1)*fx
                  if (.not. bl%fdef(b2)) then
                     bl%fm(b2) = bl%fm(b2) - pair_moment
                  else if (.not. bl%fdef(b1)) then
                     ! a rigid side takes the couple whole (module header)
                     bl%fm(b1) = bl%fm(b1) - pair_moment
                  else if (work%sga(2, i) /= work%sgb(2, i) .and. work%sw(2, i) > 0.0_wp &
                           .and. work%sw(2, i) < 1.0_wp) then
                     call edge_couple(work%sga(2, i), work%sgb(2, i), -pair_moment)
                  else
                     ! side 2 at one gridpoint (a corner, or an edge's end):
                     ! the edge that starts there (module header)
                     call contact_side(geo, c, 2, corner, edge, other)
                     if (corner == 0 .and. edge > 0) then
                        corner = edge
                        if (work%sw(2, i) >= 1.0_wp) corner = geo%corners%next(edge)
                     end if
                     if (corner > 0) call edge_couple(geo%corners%gp(corner), &
                                                      geo%corners%gp(geo%corners%next(corner)), &
                                                      -pair_moment)
                  end if
               end if
            end do
         end do
      end associate
      if (packed) call block_unpack(work, geo)
   contains
      !> Couple `moment` on the edge from gridpoint a to b: -/+ k (-ey, ex).
      subroutine edge_couple(a, b, moment)
         integer(ip), intent(in) :: a, b
         real(wp), intent(in) :: moment
         real(wp) :: ex, ey, k
         associate (gpt => geo%gridpoints)
            ex = gpt%x(b) - gpt%x(a)
            ey = gpt%y(b) - gpt%y(a)
            k = ex*ex + ey*ey
            if (k <= 0.0_wp) return
            k = moment/k
            gpt%fx(b) = gpt%fx(b) - k*ey
            gpt%fy(b) = gpt%fy(b) + k*ex
            gpt%fx(a) = gpt%fx(a) + k*ey
            gpt%fy(a) = gpt%fy(a) - k*ex
         end associate
      end subroutine edge_couple
   end subroutine contact_force_pass

   !> Velocity (vx, vy) at the point (px, py) of contact c on its side `side`
   !> (block b), group entry i of contact_force_pass: an FDEF side's by its
   !> two gridpoints (kept in work%sga, sgb, sw(side, i) for the force sums),
   !> otherwise the block's rigid motion plus, for an SDEF block, its strain
   !> rate (engine_sdef).
   pure subroutine side_velocity(work, geo, i, c, side, b, px, py, vx, vy)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: i, side
      integer(ip), intent(in) :: c, b
      real(wp), intent(in) :: px, py
      real(wp), intent(out) :: vx, vy
      integer(ip) :: ga, gb
      real(wp) :: w
      associate (bl => geo%blocks, gp => geo%gridpoints)
         if (bl%fdef(b)) then
            call contact_side_gridpoints(geo, c, side, ga, gb, w)
            work%sga(side, i) = ga; work%sgb(side, i) = gb; work%sw(side, i) = w
            vx = (1.0_wp - w)*gp%vx(ga) + w*gp%vx(gb)
            vy = (1.0_wp - w)*gp%vy(ga) + w*gp%vy(gb)
         else
            vx = bl%vx(b) - bl%vr(b)*(py - bl%yc(b))
            vy = bl%vy(b) + bl%vr(b)*(px - bl%xc(b))
            if (bl%sdef(b)) then
               vx = vx + bl%dxx(b)*(px - bl%xc(b)) + bl%dxy(b)*(py - bl%yc(b))
               vy = vy + bl%dxy(b)*(px - bl%xc(b)) + bl%dyy(b)*(py - bl%yc(b))
            end if
         end if
      end associate
   end subroutine side_velocity

   !> contact_force_pass for group `g` when every block is rigid (not FDEF,
   !> not SDEF) and the group's law is Mohr-Coulomb (JCONS 1, 2, 5): the
   !> increments, the law (mohr_coulomb_contact) and the force sums in one
   !> loop over the group's contacts, in the same order and with the same
   !> expressions as the general pass, so the results are the same to the
   !> last bit. The loop (mohr_coulomb_rigid_kernel, contact_joint_law,
   !> beside the law so that the compiler inlines the law) takes the arrays
   !> as explicit-shape dummies: their addresses stay in registers instead of
   !> being reloaded from the geometry's descriptors at each access.
   subroutine rigid_group_pass(work, geo, g, per_length, fracture_flag, dt, geometric)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(inout), target :: geo
      integer, intent(in) :: g
      logical, intent(in) :: per_length, fracture_flag, geometric
      real(wp), intent(in) :: dt
      real(wp), target :: noud(1)
      real(wp), pointer, contiguous :: ud(:)
      call ud_or_none(geo, noud, ud)
      associate (ct => geo%contacts, bl => geo%blocks, st => geo%contacts%state)
         call mohr_coulomb_rigid_kernel(work%gstart(g), work%gstart(g + 1) - 1, work%gidx, ct%block1, &
                                 ct%block2, ct%x, ct%y, ct%nx, ct%ny, ct%gap, ct%length, &
                                 st%fn, st%fs, st%un, st%us, st%flags, ud, allocated(st%ud), work%scratch, &
                                 work%gap_new, work%gprops(g), per_length, fracture_flag, dt, geometric, &
                                 work%gap_tol, work%clemin, work%beta)
      end associate
   end subroutine rigid_group_pass

   !> The joint state's ud for the rigid Mohr-Coulomb loops, or `none` when
   !> no law of the model dilates (joint_state_ud: ud is 0 throughout; the
   !> loops are then told so and never read it).
   subroutine ud_or_none(geo, none, ud)
      type(geometry_t), intent(inout), target :: geo
      real(wp), intent(inout), target :: none(:)
      real(wp), pointer, contiguous, intent(out) :: ud(:)
      if (allocated(geo%contacts%state%ud)) then
         ud => geo%contacts%state%ud
      else
         ud => none
      end if
   end subroutine ud_or_none

   !> Room in work%scratch for the edge frames of every corner id (4 reals
   !> each) and for the packed blocks (8 reals a block id): grown to the
   !> larger when corners or blocks are made, never shrunk in a CYCLE.
   subroutine scratch_ensure(work, geo)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      integer(ip) :: m
      m = max(4_ip*max(16_ip, geo%corners%n), 8_ip*max(16_ip, geo%blocks%n))
      if (allocated(work%scratch)) then
         if (size(work%scratch) < m) deallocate (work%scratch)
      end if
      if (.not. allocated(work%scratch)) allocate (work%scratch(m))
   end subroutine scratch_ensure

   !> The blocks' velocities, centroids and force sums packed into
   !> work%scratch as bp(1:8, b) = vx, vy, vr, xc, yc, fx, fy, fm for the
   !> rigid Mohr-Coulomb loops: a contact then reads and adds to one cache
   !> line of each of its blocks, not one in each of eight arrays (at 100k
   !> blocks and more the step waits on those lines). The sums start from
   !> the blocks' own values and go back by block_unpack, so they are the
   !> same to the last bit. (The pack overwrites the step's edge frames,
   !> whose geometry pass is over: contact_work_t's scratch.)
   subroutine block_pack(work, geo)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      call scratch_ensure(work, geo)
      associate (bl => geo%blocks)
         call pack_kernel(bl%n, bl%vx, bl%vy, bl%vr, bl%xc, bl%yc, bl%fx, bl%fy, bl%fm, work%scratch)
      end associate
   end subroutine block_pack

   pure subroutine pack_kernel(n, vx, vy, vr, xc, yc, fx, fy, fm, bp)
      integer(ip), intent(in) :: n
      real(wp), intent(in) :: vx(n), vy(n), vr(n), xc(n), yc(n), fx(n), fy(n), fm(n)
      real(wp), intent(out) :: bp(8, n)
      integer(ip) :: b
      do b = 1, n
         bp(1, b) = vx(b); bp(2, b) = vy(b); bp(3, b) = vr(b)
         bp(4, b) = xc(b); bp(5, b) = yc(b)
         bp(6, b) = fx(b); bp(7, b) = fy(b); bp(8, b) = fm(b)
      end do
   end subroutine pack_kernel

   !> The force sums of the pack (block_pack) back into the blocks.
   subroutine block_unpack(work, geo)
      type(contact_work_t), intent(in) :: work
      type(geometry_t), intent(inout) :: geo
      associate (bl => geo%blocks)
         call unpack_kernel(bl%n, work%scratch, bl%fx, bl%fy, bl%fm)
      end associate
   end subroutine block_unpack

   pure subroutine unpack_kernel(n, bp, fx, fy, fm)
      integer(ip), intent(in) :: n
      real(wp), intent(in) :: bp(8, n)
      real(wp), intent(inout) :: fx(n), fy(n), fm(n)
      integer(ip) :: b
      do b = 1, n
         fx(b) = bp(6, b); fy(b) = bp(7, b); fm(b) = bp(8, b)
      end do
   end subroutine unpack_kernel

   !> contact_force_pass on more than one thread (work%split): every group's
   !> entries are shared among the threads in chunks, each contact's terms go
   !> to work%cf, then each block adds its terms in the one-thread order
   !> (split_lists), so the sums are the same to the last bit.
   subroutine split_force_pass(work, geo, dt, geometric)
      type(contact_work_t), intent(inout) :: work
      type(geometry_t), intent(inout), target :: geo
      real(wp), intent(in) :: dt
      logical, intent(in) :: geometric
      integer :: g, t, nchunk, i1, i2
      logical :: per_length, fracture_flag, has_ud
      real(wp), target :: noud(1)
      real(wp), pointer, contiguous :: ud(:)
      nchunk = 4*work%nthreads
      call block_pack(work, geo)    ! (the velocities and centroids; the sums go to work%cf)
      has_ud = allocated(geo%contacts%state%ud)
      call ud_or_none(geo, noud, ud)
      associate (ct => geo%contacts, bl => geo%blocks, st => geo%contacts%state)
         do g = 1, work%ngroup
            select type (law => work%laws(work%gjcons(g))%law)
            type is (joint_mohr_coulomb_t)
               per_length = law%per_length
               fracture_flag = law%fracture_flag
            end select
            i1 = work%gstart(g)
            i2 = work%gstart(g + 1) - 1
            !$omp parallel do schedule(static) private(t)
            do t = 1, nchunk
               call mohr_coulomb_rigid_split(i1 + (t - 1)*(i2 - i1 + 1)/nchunk, &
                                             i1 + t*(i2 - i1 + 1)/nchunk - 1, work%gidx, &
                                             ct%block1, ct%block2, ct%x, ct%y, ct%nx, ct%ny, ct%gap, &
                                             ct%length, st%fn, st%fs, st%un, st%us, st%flags, &
                                             ud, has_ud, work%scratch, work%gap_new, work%gprops(g), per_length, &
                                             fracture_flag, dt, geometric, work%gap_tol, work%clemin, &
                                             work%beta, work%cf)
            end do
            !$omp end parallel do
         end do
         call gather_block_forces(bl%n, work%bptr, work%blist, work%cf, bl%fx, bl%fy, bl%fm)
      end associate
   end subroutine split_force_pass

   !> Second pass of split_force_pass: each block adds its contacts' terms in
   !> the order of its list (the one-thread order).
   subroutine gather_block_forces(n, bptr, blist, cf, fx, fy, fm)
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: bptr(*), blist(*)
      real(wp), intent(in) :: cf(4, *)
      real(wp), intent(inout) :: fx(*), fy(*), fm(*)
      integer(ip) :: b, j, i
      real(wp) :: sx, sy, sm
      !$omp parallel do schedule(static) private(b, j, i, sx, sy, sm)
      do b = 1, n
         if (bptr(b + 1) == bptr(b)) cycle
         sx = fx(b)
         sy = fy(b)
         sm = fm(b)
         do j = bptr(b), bptr(b + 1) - 1
            i = blist(j)
            if (i > 0) then
               sx = sx + cf(1, i)
               sy = sy + cf(2, i)
               sm = sm + cf(4, i)
            else
               sx = sx - cf(1, -i)
               sy = sy - cf(2, -i)
               sm = sm - cf(3, -i)
            end if
         end do
         fx(b) = sx
         fy(b) = sy
         fm(b) = sm
      end do
      !$omp end parallel do
   end subroutine gather_block_forces


end module contact_mechanics
