!> The stages of one mechanical step (manual Section 3.5) and the list a model
!> runs. A stage is in the list when the model holds its physics: a command
!> that brings zones, structures, a fluid, boundary conditions, a free field
!> (FFIELD ON), a boundary-element far field, adaptive damping or histories
!> into the scene adds its
!> stage, and a command that takes them away (DELETE, NEW, RESTART) removes it,
!> because the list is derived from the model state at the start of every
!> CYCLE (stage_list). The cycle (engine_cycle) calls each stage of the list
!> once per step; the loops over contacts, zones and gridpoints stay inside
!> the stages, flat. What the cycle hands a stage's routine is one
!> `stage_args_t` (core_motion): the step as it stands, the time at its end,
!> the step k of ncycles, the motion results and the first entity whose state
!> is not finite.
!>
!> After a CYCLE the wall time of each stage is kept in a cycle_report_t
!> (one system_clock pair per stage and step) for PRINT CYCLE.
module engine_stages
   use core_kinds, only: wp, i8
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_mechanics, only: damping_auto
   use zones_mechanics, only: zones_present
   use engine_sdef, only: sdef_present
   use engine_rigid_velocity, only: rigid_velocity_present
   use zones_boundary, only: boundary_acts
   use model_reinforcement, only: reinforcement_present
   use engine_turn, only: turn_hold_wanted
   implicit none
   private
   public :: stage_list, cycle_report_t, cycle_report_print
   public :: cycle_report_add
   public :: nstage_kinds
   public :: stage_block_motion, stage_gridpoint_motion, stage_structure_motion, &
             stage_contact_geometry, stage_contact_forces, stage_zone_stresses, &
             stage_structures, stage_fluid, stage_boundaries, stage_be, stage_clock, &
             stage_damping, stage_contact_update, stage_histories, stage_ffield, stage_sdef, &
             stage_reinforcement, stage_block_velocity, stage_turn_hold

   !> Stage ids (the order of a step is stage_list's).
   integer, parameter :: stage_block_motion = 1, stage_gridpoint_motion = 2, &
                         stage_structure_motion = 3, stage_contact_geometry = 4, &
                         stage_contact_forces = 5, stage_zone_stresses = 6, &
                         stage_structures = 7, stage_fluid = 8, stage_boundaries = 9, &
                         stage_be = 10, stage_clock = 11, stage_damping = 12, &
                         stage_contact_update = 13, stage_histories = 14, stage_ffield = 15, &
                         stage_sdef = 16, stage_reinforcement = 17, stage_block_velocity = 18, &
                         stage_turn_hold = 19
   integer, parameter :: nstage_kinds = 19

   character(len=*), parameter :: names(nstage_kinds) = [character(len=18) :: &
      'block motion', 'gridpoint motion', 'structure motion', 'contact geometry', &
      'contact forces', 'zone stresses', 'structures', 'fluid', 'boundaries', &
      'boundary elements', 'clock', 'adaptive damping', 'contact update', 'histories', 'free field', &
      'block strain', 'reinforcement', 'block velocities', 'turn hold']

   character(len=*), parameter :: whats(nstage_kinds) = [character(len=72) :: &
      'rigid blocks: gravity, damping, velocities, positions (Eq. 24, 25)', &
      'gridpoints of deformable blocks: gravity, damping, motion', &
      'nodes of structural elements: motion', &
      'gaps, normals and contact points at the new positions (SET UPCON)', &
      'relative displacements, joint laws, force sums', &
      'strain rates, constitutive models, gridpoint forces', &
      'forces of beams, cables and reinforcement', &
      'joint flow and domain pressures', &
      'applied stresses, loads, velocities, viscous dashpots, ZPRESS', &
      'the boundary-element far field', &
      'time and step count', &
      'DAMP AUTO: the damping constant follows the kinetic energy', &
      'new and broken contacts after a quarter of the contact margin of travel', &
      'HISTORY samples every NCYC steps', &
      'FFIELD: the 1-D free-field column and its forces on BOUNDARY FF points', &
      'SDEF blocks: the three strain modes, stresses, corners (Section 3.2)', &
      'REINFORCE and CABLE: cable nodes, grout, bolt springs (Section 3.10)', &
      'BOUNDARY XVEL / YVEL on corners of rigid and SDEF blocks: constraints', &
      'held by boundary stresses alone (DAMP AUTO): its turn as one body held']

   !> The stages of the last CYCLE and their wall time.
   type :: cycle_report_t
      logical :: timed = .false.             !< a CYCLE has run since the start
      integer :: n = 0
      integer :: ids(nstage_kinds) = 0
      real(wp) :: seconds(nstage_kinds) = 0.0_wp
      integer(i8) :: cycles = 0
      real(wp) :: setup = 0.0_wp             !< contacts, masses, groups, time step
      real(wp) :: wall = 0.0_wp              !< the whole CYCLE command
      !> the set-up searched for new contacts (false: skipped, nothing could
      !> have come within the margin since the last search; engine_cycle)
      logical :: opening_search = .true.
      integer :: searches = 0                !< searches during the steps (contact update)
      !> the mechanical cycles of a thermal RUN (SET NTHER), summed over its
      !> hand-overs (cycle_report_add), rather than one CYCLE command
      logical :: thermal = .false.
      integer :: handovers = 0
      !> the net force (boundary forces, loads and weight) the last "loads do
      !> not balance" note of a CYCLE named (engine_cycle, note_net_force);
      !> zero: none stands. Session state, not the model's: the note is given
      !> once for one imbalance, and again after a RESTORE
      real(wp) :: net_noted(2) = 0.0_wp
      !> the MSCALE PART note (engine_cycle, note_mscale_part) last given:
      !> gridpoints raised and the largest factor; again only when they change
      real(wp) :: mscale_noted(2) = 0.0_wp
      !> the "turn hold" note (engine_turn) was given: once a session
      logical :: turn_noted = .false.
   end type cycle_report_t

contains

   !> The stages a step of this model runs, in order.
   function stage_list(model) result(ids)
      type(model_t), intent(in) :: model
      integer, allocatable :: ids(:)
      logical :: zones, structures
      zones = zones_present(model%geometry)
      structures = .false.
      if (allocated(model%structures)) &
         structures = model%structures%elements%n > 0 .or. model%structures%nodes%n > 0
      allocate (ids(0))
      ids = [ids, stage_block_motion]
      if (rigid_velocity_present(model%bound, model%geometry)) ids = [ids, stage_block_velocity]
      if (sdef_present(model%geometry)) ids = [ids, stage_sdef]
      if (zones) ids = [ids, stage_gridpoint_motion]
      if (structures) ids = [ids, stage_structure_motion]
      ids = [ids, stage_contact_geometry, stage_contact_forces]
      if (zones) ids = [ids, stage_zone_stresses]
      if (structures) ids = [ids, stage_structures]
      if (reinforcement_present(model%reinforcement)) ids = [ids, stage_reinforcement]
      if (allocated(model%fluid)) ids = [ids, stage_fluid]
      ! the free field runs before the boundaries: its velocities feed their dashpots
      if (model%ffield%on .and. model%ffield%np > 1) ids = [ids, stage_ffield]
      if (model%bound%zp%n > 0) then
         ids = [ids, stage_boundaries]
      else if (model%bound%n > 0) then
         if (boundary_acts(model%bound, model%geometry)) ids = [ids, stage_boundaries]
      end if
      if (model%be%linked) ids = [ids, stage_be]
      ids = [ids, stage_clock]
      if (model%mech%damping == damping_auto) ids = [ids, stage_damping]
      if (turn_hold_wanted(model)) ids = [ids, stage_turn_hold]
      ids = [ids, stage_contact_update]
      if (model%hist%n > 0) ids = [ids, stage_histories]
   end function stage_list

   !> Add the timing of one mechanical hand-over of a thermal RUN (`part`, a
   !> CYCLE's report) to `total`; `first`: the RUN's first hand-over, which
   !> replaces what `total` held. Stage times are summed by stage id.
   subroutine cycle_report_add(total, part, first)
      type(cycle_report_t), intent(inout) :: total
      type(cycle_report_t), intent(in) :: part
      logical, intent(in) :: first
      integer :: k, j
      if (first) then
         total = part
         total%searches = part%searches + merge(1, 0, part%opening_search)
         total%thermal = .true.
         total%handovers = 1
         return
      end if
      do k = 1, part%n
         j = findloc(total%ids(1:total%n), part%ids(k), dim=1)
         if (j == 0) then
            total%n = total%n + 1
            j = total%n
            total%ids(j) = part%ids(k)
         end if
         total%seconds(j) = total%seconds(j) + part%seconds(k)
      end do
      total%cycles = total%cycles + part%cycles
      total%searches = total%searches + part%searches + merge(1, 0, part%opening_search)
      total%setup = total%setup + part%setup
      total%wall = total%wall + part%wall
      total%handovers = total%handovers + 1
      total%net_noted = part%net_noted
      total%mscale_noted = part%mscale_noted
      total%turn_noted = part%turn_noted
   end subroutine cycle_report_add

   !> PRINT CYCLE: the stages this model runs now and, after a CYCLE, each
   !> stage's share of that CYCLE's wall time.
   subroutine cycle_report_print(report, model, out)
      type(cycle_report_t), intent(in) :: report
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer, allocatable :: ids(:)
      integer :: i, k
      real(wp) :: stepping, other
      character(len=200) :: line
      ids = stage_list(model)
      call out%line('Stages of a step of this model, in order:')
      do i = 1, size(ids)
         write (line, '(3x,a18,2x,a)') names(ids(i)), trim(whats(ids(i)))
         call out%line(trim(line))
      end do
      if (.not. report%timed) then
         call out%line('No CYCLE has run yet: no timing.')
         return
      end if
      if (report%thermal) then
         write (line, '(a,i0,a,i0,a,a,a)') 'Last RUN: ', report%cycles, &
            ' mechanical steps in ', report%handovers, ' hand-overs, ', &
            trim(adjustl(fmt_real(report%wall, 11, 4))), ' s wall time (thermal steps excluded)'
      else
         write (line, '(a,i0,a,a,a)') 'Last CYCLE: ', report%cycles, ' steps, ', &
            trim(adjustl(fmt_real(report%wall, 11, 4))), ' s wall time'
      end if
      call out%line(trim(line))
      call out%line('   stage                 seconds   share')
      stepping = 0.0_wp
      do k = 1, report%n
         stepping = stepping + report%seconds(k)
         call row(names(report%ids(k)), report%seconds(k))
      end do
      call row('set-up', report%setup)
      other = max(0.0_wp, report%wall - report%setup - stepping)
      call row('other', other)
      if (report%thermal) then
         write (line, '(a,i0,a)') 'Searches for new contacts: ', report%searches, &
            ' (hand-overs and contact updates)'
      else if (report%opening_search) then
         write (line, '(a,i0,a)') 'Searches for new contacts: at the start and ', report%searches, &
            ' during the steps (contact update)'
      else
         write (line, '(a,i0,a)') 'Searches for new contacts: none at the start (no command '// &
            'changed the contacts and no block travelled a quarter of the margin since the '// &
            'last search), ', report%searches, ' during the steps (contact update)'
      end if
      call out%line(trim(line))
   contains
      subroutine row(name, seconds)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: seconds
         real(wp) :: share
         character(len=18) :: padded
         padded = name
         share = 0.0_wp
         if (report%wall > 0.0_wp) share = 100.0_wp*seconds/report%wall
         write (line, '(3x,a18,2x,a,f7.1,a)') padded, fmt_real(seconds, 11, 4), share, ' %'
         call out%line(trim(line))
      end subroutine row
   end subroutine cycle_report_print

end module engine_stages
