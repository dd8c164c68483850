!> The explicit cycle (manual Sections 3.5, 3.6 and 5.3; CYCLE n).
!>
!> Stages are chosen from what the model holds at the start of every CYCLE
!> (engine_stages, stage_list): rigid-block motion and contact forces always;
!> zone, structure, fluid, boundary, boundary-element, damping and history
!> stages join when the model has those physics, so a rigid-block deck runs
!> none of their code. Each step calls every stage of the list once.
!>
!> One step:
!>    motion    velocities from the force sums of the last step (Eq. 24/28),
!>              new positions (Eq. 25), corners and rounding circles follow
!>    contacts  gap / normal / point at the new positions; an overlap beyond
!>              OVTOL undoes the step and ends the CYCLE with the contact's
!>              id and position; then relative displacements, joint laws,
!>              force sums (contact_mechanics)
!>    update    when some block has travelled a quarter of the contact
!>              margin since the last scan: new and broken contacts,
!>              lengths, joint-law groups and time step again
!>    history   every NCYC steps
!>
!> Time step: dt = fb * 2 sqrt(m_min / k_max) (FRACTION fb, default 0.1),
!> m_min the smallest inertial mass of a free block, k_max the largest
!> contact stiffness (kn or ks, times the contact length for area contacts),
!> and for every free block also 2 sqrt(m / (k_mat sqrt(area))) with k_mat
!> the stiffest joint material, so that dt does not jump when a falling
!> block first touches. Contacts whose stiffness depends on their state
!> (JCONS 3 with JEN / JES) count at their current stiffness, and the step
!> is recomputed as soon as one is stiffer than it allows. With stiffness-
!> proportional damping beta the step is reduced by sqrt(1 + l^2) - l,
!> l = beta / dt_crit.
!>
!> Damping (DAMP): AUTO adapts the mass-proportional constant alpha every
!> step so that the energy taken by damping is `fac` times the absolute
!> change of kinetic energy (Cundall's adaptive damping): below, alpha is
!> multiplied by mult2 (1.05); above, by mult1 (0.99); alpha stays within
!> [1e-6, 1] / dt, starting from sqrt(k_max / m_min), and from 1 / dt after a
!> static load change (model_mechanics damping_load_changed; with elastic
!> zones 2 w of the driven mode instead, damping_probe). Rayleigh: fcrit at freq gives alpha = fcrit*w, beta =
!> fcrit/w (MASS only: alpha = 2 fcrit w; STIFF only: beta = 2 fcrit / w).
module engine_cycle
   use core_constants, only: pi
   use core_kinds, only: wp, ip, i8
   use core_motion, only: motion_step, motion_result_t, motion_add, stage_args_t
   use model_properties, only: prop_bulk, prop_density, prop_jkn, prop_jks, prop_kn, prop_ks, prop_tf, &
                                 prop_shear, prop_jtensile
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use core_output, only: output_t, fmt_real, format_real, itoa
   use core_progress, only: progress_t
   use model_state, only: model_t
   use model_mechanics, only: damping_auto, damping_rayleigh, damping_local, zone_fraction, mechanics_t
   use model_geometry, only: geometry_t, geometry_live_blocks, contact_corner1, contact_corner2
   use model_boundary, only: boundary_t, bc_velocity, bc_viscous, vis_x, vis_y, boundary_has_traction, &
                             bh_sine, bh_cosine
   use model_zones, only: vfix_x, vfix_y
   use model_zone_fields, only: zone_area, principal_stresses
   use contact_kinematics, only: overlap_judge, contact_overlap_limit, contact_overlap_bound, &
                                 overlap_bound_radii, overlap_bound_round, overlap_bound_edge, &
                                 overlap_bound_switch, switch_fraction
   use contact_update, only: contact_scan, contact_margin
   use contact_refresh, only: geometry_refresh
   use contact_mechanics, only: contact_work_t, contact_work_setup, contact_groups_build, &
                                contact_geometry_pass, contact_force_pass, contact_stiffness_max, &
                                contact_state_stiffness
   use engine_rigid, only: motion_work_t, rigid_masses, rigid_motion, motion_save, motion_restore, &
                           overlap_screen
   use engine_history, only: history_values
   use model_history, only: history_record
   use zones_boundary, only: boundary_cycle_start, boundary_step, boundary_cycle_end, &
                             boundary_traction_force
   use zones_pressure, only: zones_pressure_step
   use zones_viscous, only: viscous_work_t, viscous_prepare, viscous_step, viscous_fit_masses
   use zones_ffield, only: ffield_work_t, ffield_prepare, ffield_column_step, &
                           ffield_column_forces, ffield_apply, ffield_cycle_end
   use be_far_field, only: be_ensure, be_step, be_stiffness_bound
   use structure_mechanics, only: structure_work_t, structure_prepare, structure_timestep, &
                                  structure_fit_masses, structure_motion, structure_force_pass, &
                                  structure_save, structure_restore
   use reinforce_mechanics, only: reinforce_prepare, reinforce_step, reinforce_save, &
                                  reinforce_restore
   use contact_domains, only: domain_rebuild, domain_release
   use fluid_flow, only: fluid_work_t, fluid_sync, fluid_prepare, fluid_step, fluid_forces, &
                         fluid_mech_dt, fluid_joint_stiffness, fluid_flow_dt, fluid_pressure_scale, &
                         fluid_closed_count
   use zones_mechanics, only: zone_work_t, zones_prepare, zones_timestep, zones_stress_pass, &
                              zones_stiffness, zones_clear_forces, gridpoint_motion, &
                              zones_block_centroids
   use engine_stages, only: cycle_report_t, stage_list, stage_block_motion, &
                            stage_gridpoint_motion, stage_structure_motion, &
                            stage_contact_geometry, stage_contact_forces, stage_zone_stresses, &
                            stage_structures, stage_fluid, stage_boundaries, stage_be, stage_reinforcement, &
                            stage_clock, stage_damping, stage_contact_update, stage_histories, &
                            stage_ffield, stage_sdef, stage_block_velocity, stage_turn_hold
   use engine_turn, only: model_held, turn_hold_wanted, turn_hold_step
   use engine_rigid_velocity, only: rigid_velocity_t, rigid_velocity_build, rigid_velocity_step
   use engine_sdef, only: sdef_prepare, sdef_motion, sdef_timestep, sdef_save, sdef_restore
   implicit none
   private
   public :: cycle_run, cycle_prepare, cycle_timestep, cycle_report_t
   public :: solve_t, cycle_force_ratio, search_base

   !> SOLVE (an extension, issue 24): cycle_run stops when the ratio of the
   !> maximum unbalanced force to the mean contact (or gridpoint) force falls
   !> below `ratio_limit`; it reports the ratio reached and what ended it.
   type :: solve_t
      real(wp) :: ratio_limit = 1.0e-5_wp
      real(wp) :: ratio = -1.0_wp        !< last measured (< 0: undefined, no force)
      logical :: reached = .false.       !< the ratio fell below the limit
      logical :: interrupted = .false.   !< Ctrl-C or SIGTERM ended it
      !> nothing to balance: no contact, weight or stress gives a force and no
      !> unbalanced force acts (a lone FIXed block), so SOLVE ends at once
      logical :: idle = .false.
      !> the round-off floor of the forces (cycle_force_ratio), worked out at
      !> the SOLVE's first measurement and again when the step changes
      real(wp) :: floor = 0.0_wp
      !> the step the floor was worked out for (< 0: not yet in this SOLVE)
      real(wp) :: floor_dt = -1.0_wp
      !> nothing holds the model and its loads do not balance (note_net_force):
      !> it would accelerate as one body, so SOLVE runs no cycle
      logical :: unheld = .false.
      integer(i8) :: cycles = 0          !< cycles done
   end type solve_t

   !> The step is computed for stiffnesses of state-dependent contacts this
   !> much above their current value, so that a stiffening joint does not
   !> ask for a new step every cycle (cycle_run).
   real(wp), parameter :: state_headroom = 1.05_wp


   !> The work arrays of one CYCLE (cycle_run): contacts, block motion,
   !> zones, viscous boundaries, structures, fluid, free field.
   type :: cycle_work_t
      type(contact_work_t) :: cw
      type(motion_work_t) :: mw
      type(zone_work_t) :: zw
      type(viscous_work_t) :: vw
      type(structure_work_t) :: sw
      type(fluid_work_t) :: fw
      type(ffield_work_t) :: ffw
      !> mass-proportional Rayleigh damping constant of the CYCLE (damping_constants)
      real(wp) :: alpha_rayleigh = 0.0_wp
      !> nothing mechanical bounds the step (no free mass, or nothing stiff):
      !> cycle_timestep kept an arbitrary one (fluid_limit_dt)
      logical :: dt_unbound = .false.
      !> the largest overlap of a contact after the set-up's scan (the first
      !> step's corner copies are skipped when it is small: motion_work_t)
      real(wp) :: scan_overlap = huge(1.0_wp)
      !> the set-up searched for new contacts (false: search_skippable held)
      logical :: searched = .true.
      !> searches for new contacts during the steps (the contact update)
      integer :: searches = 0
   end type cycle_work_t
   !> The cause and remedy of an overlap under a step load on unloaded
   !> joints (step_load_on_unloaded_joints), for the first CYCLE's note and
   !> the stop's message.
   character(len=*), parameter :: step_load_words = 'the joints carried no stress when this CYCLE ' &
      //'began and its loads (BOUNDARY STRESS, GRAVITY) reach them at once: a joint closes by up to ' &
      //'twice its static closure (stress / JKN) and an inclined one slides before its normal stress ' &
      //'gives it friction; INSITU STRESS with the field the loads make (YGRAD for the weight; manual ' &
      //'Section 4, INSITU) puts it on the joints and blocks first, at rest'

contains

   !> Contacts, masses, groups, damping constants and the time step before
   !> stepping.
   !> `searched`: the CYCLE command's geometry_refresh has just updated the
   !> contacts of a cycled model after a cut with a search over the whole
   !> model at the contact margin (issue 23: a cut after cycling searched
   !> twice, there and here, at the same positions; the second found
   !> nothing new). It counts as the opening search: recorded, not repeated.
   subroutine cycle_prepare(model, wk, error, searched)
      type(model_t), intent(inout) :: model
      type(cycle_work_t), intent(inout) :: wk
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: searched
      integer(ip) :: nnew, nbroken
      real(wp) :: margin, rhow, ywtab
      logical :: skip, refreshed
      associate (geo => model%geometry, mech => model%mech)
         if (geometry_live_blocks(geo) == 0) then
            call set_error(error, 'CYCLE: there are no blocks (give BLOCK first)')
            return
         end if
         ! before anything is touched: a refused CYCLE leaves the model as it was
         call check_block_materials(model, error)
         if (allocated(error)) return
         refreshed = .false.
         if (present(searched)) refreshed = searched .and. geo%mechanical .and. geo%contacts_valid
         if (refreshed) call search_done(model, contact_margin(geo))
         skip = search_skippable(model)
         ! a model not cycled yet whose contacts are out of date (a cutting
         ! command or GENERATE since they were made; the CYCLE command brings
         ! them up to date before it comes here, a thermal RUN handing over to
         ! NMECH mechanical steps does not): they are made anew, as CYCLE's
         ! are, not updated in place from corners that may be gone
         if (.not. geo%mechanical .and. .not. geo%contacts_valid) call geometry_refresh(geo)
         ! a dry model (no FLUID) reads no domain during the CYCLE: they are
         ! given back now and built from the contacts of the moment when
         ! something reads them (contact_domains' domain_release; issue 23)
         if (.not. allocated(model%fluid)) call domain_release(geo)
         margin = contact_margin(geo)
         if (.not. geo%mechanical) then
            ! contacts of the set-up start with the exact gaps of the cut blocks
            geo%mechanical = .true.
         end if
         ! the contacts kept are brought up to date in any case (normals,
         ! points, the separated broken, lengths); the search for new ones
         ! only when something may have come within the margin since the last
         ! (search_skippable); the travel since it then carries on
         call contact_scan(geo, margin, nnew, nbroken, wk%scan_overlap, search=.not. skip)
         if (.not. skip) call search_done(model, margin)
         wk%searched = .not. skip .or. refreshed
         wk%searches = 0
         geo%contacts_valid = .true.
         call rigid_masses(geo, model%materials, mech%mscale .and. .not. mech%mscale_part, &
                           mech%mscale_block, wk%mw, error)
         if (allocated(error)) return
         call zones_prepare(geo, model%materials, mech%mscale, mech%mscale_zone, mech%mscale_part, &
                            mech%mscale_tdel, zone_fraction(mech), wk%zw, error)
         if (allocated(error)) return
         if (model%be%linked) then
            call be_ensure(model%be, error)
            if (allocated(error)) return
            if (wk%zw%active) call be_stiffness_bound(model%be, geo, wk%zw%kgp)
         end if
         call contact_work_setup(wk%cw, geo, error)
         if (allocated(error)) return
         wk%cw%switch_tol = 1.0e-3_wp*margin
         call contact_groups_build(wk%cw, geo, model%materials, mech%clemin, mech%clemin_auto, &
                                   error)
         if (allocated(error)) return
         if (wk%zw%active) then
            call viscous_prepare(wk%vw, model%bound, geo, model%materials, wk%zw%m_in, &
                                 wk%mw%m_in, wk%mw%i_in, error)
         else
            call viscous_prepare(wk%vw, model%bound, geo, model%materials, [real(wp) ::], &
                                 wk%mw%m_in, wk%mw%i_in, error)
         end if
         if (allocated(error)) return
         ! MSCALE PART tdel: gridpoints too light for their dashpots at tdel
         ! get heavier (zones_viscous), so the step is tdel
         if (wk%zw%active .and. wk%vw%n > 0 .and. mech%mscale .and. mech%mscale_part .and. &
             mech%mscale_tdel > 0.0_wp .and. wk%vw%dt_max < mech%mscale_tdel) then
            call viscous_fit_masses(wk%vw, model%bound, geo, wk%zw%m_in, mech%mscale_tdel)
            call viscous_prepare(wk%vw, model%bound, geo, model%materials, wk%zw%m_in, &
                                 wk%mw%m_in, wk%mw%i_in, error)
            if (allocated(error)) return
         end if
         ! the free field (FFIELD ON): its column, its points, its stable step
         wk%vw%dt_ffield = huge(1.0_wp)
         rhow = 0.0_wp
         ywtab = huge(1.0_wp)
         if (allocated(model%fluid)) then
            if (model%fluid%eff) then
               rhow = model%fluid%rhow
               ywtab = model%fluid%ywtab
            end if
         end if
         call ffield_prepare(wk%ffw, model%ffield, model%bound, geo, model%materials, wk%vw, &
                             zone_fraction(mech), &
                             merge(mech%mscale_tdel, 0.0_wp, mech%mscale .and. mech%mscale_part), &
                             rhow, ywtab, error)
         if (allocated(error)) return
         wk%vw%dt_ffield = wk%ffw%dt_max
         ! structural elements only when the model has them
         wk%sw%active = .false.
         if (allocated(model%structures)) then
            call structure_prepare(model%structures, model%materials, wk%sw, error)
            if (allocated(error)) return
         end if
         ! reinforcement (REINFORCE, CABLE) only when the model has it
         wk%sw%rw%active = .false.
         if (allocated(model%reinforcement)) then
            if (wk%zw%active) then
               call reinforce_prepare(model%reinforcement, geo, model%materials, wk%mw%m_in, &
                                      wk%zw%m_in, wk%sw%rw, error)
            else
               call reinforce_prepare(model%reinforcement, geo, model%materials, wk%mw%m_in, &
                                      [real(wp) ::], wk%sw%rw, error)
            end if
            if (allocated(error)) return
         end if
         call damping_constants(model, wk%cw, wk%alpha_rayleigh)
         call sdef_prepare(geo, model%materials, mech, wk%mw%m_in, wk%cw%beta, wk%mw%sd, error)
         if (allocated(error)) return
         call fluid_ready(model, wk%fw)
         mech%dt = cycle_timestep(model, wk, wk%dt_unbound)
         call note_state_stiffness(wk%cw, geo)
         call fluid_limit_dt(model, wk)
         ! MSCALE: structure nodes too light for the step get heavier instead
         if (wk%sw%active .and. mech%mscale) &
            call structure_fit_masses(model%structures, wk%sw, mech%dt, zone_fraction(mech))
      end associate
   end subroutine cycle_prepare

   !> A CYCLE may skip its opening search for new contacts (Issue 23): the
   !> model has cycled and its contacts are up to date, no command since
   !> the last search could have changed the geometry, the contacts, the
   !> rounding or the joint properties (mech%search_current; the block,
   !> corner and contact lists and the margin are as then, a second guard),
   !> and no block point has travelled more than a quarter of the margin
   !> since: the contact update during the steps would not search either.
   !> A corner that was not within the margin of another block at the last
   !> search is then still more than half the margin from it (each of the
   !> two has moved at most a quarter), so it carries no force yet; it is
   !> found by the contact update once the travel since the last search,
   !> carried across CYCLE commands, passes a quarter of the margin, as
   !> within one CYCLE.
   logical function search_skippable(model) result(skip)
      type(model_t), intent(in) :: model
      real(wp) :: margin
      associate (geo => model%geometry, mech => model%mech)
         skip = mech%search_current .and. geo%mechanical .and. geo%contacts_valid
         if (.not. skip) return
         margin = contact_margin(geo)
         skip = mech%search_sizes(1) == geo%blocks%n .and. mech%search_sizes(2) == geo%corners%n &
                .and. mech%search_sizes(3) == geo%contacts%n .and. &
                mech%search_margin == margin .and. mech%motion_since_scan <= 0.25_wp*margin
      end associate
   end function search_skippable

   !> For geometry_refresh's `since` before a CYCLE (issue 23): the number
   !> of corners at the last search for new contacts when that search still
   !> stands but for blocks cut, deleted or re-ringed since (only the
   !> commands that keep the search or cut locally came after it:
   !> commands_session, which otherwise sets search_sizes to -1; a corner
   !> compaction renumbers the count with the corners, model_compact), the
   !> margin is as then and no block has travelled a quarter of it since
   !> (the bound search_skippable uses: a corner of two unchanged blocks not
   !> within the margin then is more than half of it away and is found by
   !> the contact update before it touches); 0 (search everything) if not.
   integer(ip) function search_base(model) result(base)
      type(model_t), intent(in) :: model
      real(wp) :: margin
      base = 0
      associate (geo => model%geometry, mech => model%mech)
         if (.not. (geo%mechanical .and. mech%search_sizes(2) > 0)) return
         margin = contact_margin(geo)
         if (mech%search_sizes(1) <= geo%blocks%n .and. mech%search_sizes(2) <= geo%corners%n &
             .and. mech%search_margin == margin .and. mech%motion_since_scan <= 0.25_wp*margin) &
            base = mech%search_sizes(2)
      end associate
   end function search_base

   !> After a search for new contacts (the CYCLE's opening scan, the
   !> contact update, or geometry_refresh's on a cycled model just before
   !> the CYCLE, cycle_prepare's `searched`): what search_skippable compares.
   subroutine search_done(model, margin)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: margin
      associate (geo => model%geometry, mech => model%mech)
         mech%search_current = .true.
         mech%search_sizes = [geo%blocks%n, geo%corners%n, geo%contacts%n]
         mech%search_margin = margin
         mech%motion_since_scan = 0.0_wp
      end associate
   end subroutine search_done

   !> Fluid stage set-up (only when the model has a fluid): domains up to
   !> date, pressures matched to them, apertures, volumes.
   subroutine fluid_ready(model, fw)
      type(model_t), intent(inout) :: model
      type(fluid_work_t), intent(inout) :: fw
      if (.not. allocated(model%fluid)) return
      if (.not. model%geometry%domains_valid) call domain_rebuild(model%geometry)
      call fluid_sync(model%fluid, model%geometry)
      call fluid_prepare(model%fluid, model%geometry, model%materials, fw)
   end subroutine fluid_ready

   !> The fluid's stiffness on the joints bounds the mechanical step
   !> (transient flow only): rigid blocks by fluid_mech_dt, the gridpoints
   !> of fully-deformable blocks by Kw / a added to their joint stiffness
   !> (fluid_joint_stiffness, zones_timestep) with FRACTION fz. When nothing
   !> mechanical bounds the step (all blocks fixed), the step is the stable
   !> flow step (Eq. 57 with FRACTION fw): the manual's "if less than the
   !> mechanical timestep, is used in the analysis", rather than an
   !> arbitrary step paid for with thousands of flow sub-steps.
   subroutine fluid_limit_dt(model, wk)
      type(model_t), intent(inout) :: model
      type(cycle_work_t), intent(inout) :: wk
      real(wp) :: mmin, kf, kff, dtf, kmat, kmax, dtsz
      integer(ip) :: b
      if (.not. allocated(model%fluid)) return
      if (wk%dt_unbound .and. model%fluid%bulkw > 0.0_wp .and. .not. model%fluid%sflow) then
         dtf = fluid_flow_dt(model%fluid, model%geometry, wk%fw, model%mech%frac_fluid)
         if (dtf < huge(1.0_wp)) model%mech%dt = dtf
      end if
      kf = fluid_joint_stiffness(model%fluid, model%geometry, kff)
      if (wk%zw%active .and. kf > 0.0_wp) model%mech%dt = min(model%mech%dt, &
         zone_fraction(model%mech)*zones_timestep(model%geometry, wk%zw, kf))
      ! the strain modes of SDEF blocks feel the fluid on their joints too
      ! (the domain volumes follow their corners): the joints' stiffness and
      ! the fluid's in parallel
      if (wk%mw%sd%active .and. kf > 0.0_wp) then
         call joint_stiffness_max(model, kmat, kmax)
         dtsz = sdef_timestep(model%geometry, wk%mw%sd, wk%mw%m_in, wk%mw%i_in, kmat + kf, &
                              kmax + kff)
         model%mech%dt = min(model%mech%dt, zone_fraction(model%mech)*dtsz)
      end if
      mmin = huge(1.0_wp)
      do b = 1, model%geometry%blocks%n
         if (.not. model%geometry%blocks%live(b) .or. model%geometry%blocks%fixed(b)) cycle
         if (model%geometry%blocks%fdef(b) .or. wk%mw%m_in(b) <= 0.0_wp) cycle
         mmin = min(mmin, wk%mw%m_in(b))
      end do
      if (mmin == huge(1.0_wp)) return
      model%mech%dt = min(model%mech%dt, fluid_mech_dt(model%fluid, model%geometry, wk%fw, mmin, &
                                                       model%mech%frac_block))
   end subroutine fluid_limit_dt

   !> Every block that moves needs the properties of its material (manual 4.5
   !> PROPERTY, Block Material Properties: density for every block, K and G for
   !> fully deformable ones): a rigid block that is not FIXed needs DENSITY; a
   !> zoned block needs DENSITY and, unless excavated (CONS 0), K and G. CHANGE
   !> MAT=n to a material not (yet) given by PROPERTY would otherwise leave the
   !> block or its gridpoints with zero mass. The first such block is named with
   !> its material and every missing property.
   subroutine check_block_materials(model, error)
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b
      integer :: mat
      logical :: zoned, sdef
      character(len=:), allocatable :: missing, give, what
      associate (bl => model%geometry%blocks, mats => model%materials)
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            zoned = bl%fdef(b) .and. bl%nzone(b) > 0
            if (.not. zoned .and. bl%fixed(b)) cycle
            mat = int(bl%material(b))
            missing = ''
            give = ''
            if (mats%get(mat, prop_density) <= 0.0_wp) call add('DENSITY')
            sdef = bl%sdef(b) .and. .not. zoned
            if (sdef .and. .not. any([1_ip, 4_ip] == bl%cons(b))) then
               call set_error(error, 'CYCLE: SDEF block '//itoa(b)//' (centroid '// &
                              format_real(bl%xc(b))//', '//format_real(bl%yc(b))// &
                              ') has CONS '//itoa(bl%cons(b))//'; SDEF blocks know CONS 1 '// &
                              '(elastic) and 4 (Griffith): give CHANGE CONS 1 or 4; nothing was changed')
               return
            end if
            if ((zoned .or. sdef) .and. bl%cons(b) /= 0) then
               if (mats%get(mat, prop_bulk) <= 0.0_wp) call add('K')
               if (mats%get(mat, prop_shear) <= 0.0_wp) call add('G')
            end if
            if (sdef .and. bl%cons(b) == 4) then
               if (mats%get(mat, prop_tf) <= 0.0_wp) call add('TF')
            end if
            if (len(missing) == 0) cycle
            what = merge('zoned', 'rigid', zoned)
            if (sdef) what = 'SDEF'
            if (.not. any_given(mat)) then
               missing = missing//' (material '//itoa(mat)//' has no properties at all)'
            end if
            call set_error(error, 'CYCLE: block '//itoa(b)//' ('//what//', centroid '// &
                           format_real(bl%xc(b))//', '// &
                           format_real(bl%yc(b))//') has material '//itoa(mat)// &
                           ' without '//missing//': give PROPERTY MAT='//itoa(mat)//give// &
                           ' (or CHANGE MAT to a material that has them); nothing was changed')
            return
         end do
      end associate
   contains
      subroutine add(name)
         character(len=*), intent(in) :: name
         if (len(missing) > 0) missing = missing//', '
         missing = missing//name
         give = give//' '//name//'=..'
      end subroutine add
      logical function any_given(m)
         integer, intent(in) :: m
         any_given = .false.
         if (m < 1 .or. m > model%materials%nmat) return
         any_given = any(model%materials%given(:, m))
      end function any_given
   end subroutine check_block_materials

   !> First CYCLE: a joint takes a normal stress change of JKN x t before
   !> Contact Overlap Too Great stops the run (manual Section 5.3), t its
   !> contacts' tolerance: OVTOL where SET OVTOL gave it, else from the
   !> contact's rounded corners (contact_overlap_limit: OVTOL = d / 2 to
   !> 2 d), d for two right-angled corners, the figure named. Next to an opening the
   !> stress on a joint changes by up to twice the largest stress of the
   !> field (Kirsch: the hoop stress 3 s1 - s3). A new user's ROUND 0.005
   !> with JKN 5e9 takes 25 MPa at right-angled corners in an 18 MPa field. Say so before cycling,
   !> once, naming the remedy.
   subroutine note_overlap_headroom(model, ovtol, step_load, out)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: ovtol
      logical, intent(in) :: step_load
      type(output_t), intent(inout) :: out
      real(wp) :: smax, kmin, kn, tmax
      integer(ip) :: c, i, jlow
      character(len=2000) :: line
      character(len=5) :: tname
      smax = 0.0_wp
      kmin = huge(1.0_wp)
      jlow = 0
      associate (ct => model%geometry%contacts, b => model%bound)
         do c = 1, ct%n
            if (.not. ct%live(c) .or. ct%jmat(c) <= 0) cycle
            kn = model%materials%get(int(ct%jmat(c)), prop_jkn)
            if (kn <= 0.0_wp) cycle
            if (kn < kmin) then
               kmin = kn
               jlow = ct%jmat(c)
            end if
            if (ct%length(c) > 0.0_wp) smax = max(smax, abs(ct%state%fn(c))/ct%length(c))
         end do
         if (jlow == 0) return
         do i = 1, b%n
            ! the totals and what this CYCLE adds to them (BOUNDARY STRESS given
            ! before the first CYCLE is still an increment)
            smax = max(smax, abs(b%sxx_next(i) + b%dsxx_next(i)), abs(b%syy_next(i) + b%dsyy_next(i)), &
                       abs(b%sxy_next(i) + b%dsxy_next(i)), abs(b%sxx_prev(i) + b%dsxx_prev(i)), &
                       abs(b%syy_prev(i) + b%dsyy_prev(i)), abs(b%sxy_prev(i) + b%dsxy_prev(i)))
         end do
      end associate
      ! the weight's stress at the foot of the model (a fixed base or rollers
      ! carry it before any contact does at the first step)
      smax = max(smax, weight_stress(model))
      tmax = ovtol
      tname = 'OVTOL'
      if (.not. model%mech%ovtol > 0.0_wp .and. model%geometry%round > ovtol) then
         tmax = model%geometry%round
         tname = 'ROUND'
      end if
      if (2.0_wp*smax <= kmin*tmax) return
      write (line, '(a,i0,11a)') 'CYCLE: note: the joints of material ', jlow, ' take a normal ' &
         //'stress change of JKN x ', tname, ' = ', trim(adjustl(fmt_real(kmin*tmax, 10, 3))), &
         ' (', tname, ' ', trim(adjustl(fmt_real(tmax, 10, 3))), &
         ') before Contact Overlap Too Great stops the run (manual Section 5.3; by default the ' &
         //'tolerance of a contact between right-angled corners, from OVTOL to 2 ROUND by its ' &
         //'corners'' angles), less than ' &
         //'twice the largest stress in the model (', trim(adjustl(fmt_real(smax, 10, 3))), &
         '), which an opening or a loaded edge can bring: a ROUND of a few percent of the ' &
         //'block edges (manual Section 3.3, its half is OVTOL), a stiffer JKN or a larger SET OVTOL ' &
         //'gives room'
      if (step_load) line = trim(line)//'; '//step_load_words
      call out%line(trim(line))
   end subroutine note_overlap_headroom

   !> The joints carry no stress and this CYCLE loads them (BOUNDARY
   !> STRESS, GRAVITY): a model neither INSITU nor an earlier CYCLE put in
   !> equilibrium. The load reaches the joints at once: a joint closes by up
   !> to twice its static closure s / JKN before the damping takes the
   !> overshoot (a step load on a spring), and an inclined joint takes its
   !> shear before the normal stress that gives it friction, so it slides.
   !> Found on the new user's jointed tunnels under BOUNDARY STRESS alone
   !> (docs/robustness.md, round 3): stopped on Contact Overlap Too Great
   !> in the first 16 to 550 steps; the same decks with INSITU STRESS of
   !> the same field stayed at rest to 1e-14 m (manual Section 4, INSITU:
   !> it "sets initial zone stresses in all fully-deformable blocks and
   !> joints").
   logical function step_load_on_unloaded_joints(model) result(step)
      type(model_t), intent(in) :: model
      integer(ip) :: c, i
      logical :: joints, loads
      step = .false.
      joints = .false.
      associate (ct => model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c) .or. ct%jmat(c) <= 0) cycle
            if (ct%state%fn(c) /= 0.0_wp) return
            joints = .true.
         end do
      end associate
      if (.not. joints) return
      loads = any(model%gravity /= 0.0_wp)
      do i = 1, model%bound%n
         if (loads) exit
         loads = boundary_has_traction(model%bound, i)
      end do
      step = loads
   end function step_load_on_unloaded_joints

   !> '' unless a BOUNDARY STRESS pulls on the model (its largest principal
   !> stress on a boundary point's edges is positive: stresses are positive
   !> in tension, UDEC manual (ICG1.5, 1989), Section 4.1) beyond the
   !> tensile strength (JTENSILE, 0 by default) of the weakest joint
   !> material in the model; then the words saying so, naming the stress and
   !> where. A jointed model so pulled comes apart: the boundary blocks fly
   !> off and collide (a new user's `BOUNDARY STRESS 5e6 0 5e6` on a jointed
   !> box stopped after 5015 cycles on Contact Overlap Too Great 3.7 m
   !> outside the model, and the stop's advice spoke of JKN and INSITU). A
   !> stress given with a SINE or COSINE history swings through both signs
   !> and is left out, as BOUNDARY's own note does.
   function boundary_pull_words(model) result(text)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: text
      integer(ip) :: c, i, k, worst
      real(wp) :: tens, smin, smax, angle, s1
      real(wp) :: st(3, 2)
      text = ''
      tens = huge(1.0_wp)
      associate (ct => model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c) .or. ct%jmat(c) <= 0) cycle
            tens = min(tens, model%materials%get(int(ct%jmat(c)), prop_jtensile))
         end do
      end associate
      if (tens == huge(1.0_wp)) return
      s1 = tens
      worst = 0
      associate (bnd => model%bound)
         do i = 1, bnd%n
            if (.not. boundary_has_traction(bnd, i)) cycle
            if (any(bnd%hx(i) == [bh_sine, bh_cosine]) .or. any(bnd%hy(i) == [bh_sine, bh_cosine])) &
               cycle
            st(:, 1) = [bnd%sxx_prev(i) + bnd%dsxx_prev(i), bnd%syy_prev(i) + bnd%dsyy_prev(i), &
                        bnd%sxy_prev(i) + bnd%dsxy_prev(i)]
            st(:, 2) = [bnd%sxx_next(i) + bnd%dsxx_next(i), bnd%syy_next(i) + bnd%dsyy_next(i), &
                        bnd%sxy_next(i) + bnd%dsxy_next(i)]
            do k = 1, 2
               ! a pure shear (sxx = syy = 0) has principal stresses +-sxy
               ! whatever its sign: not a pull
               if (st(1, k) == 0.0_wp .and. st(2, k) == 0.0_wp) cycle
               call principal_stresses(st(1, k), st(2, k), st(3, k), smin, smax, angle)
               if (smax > s1) then
                  s1 = smax
                  worst = i
               end if
            end do
         end do
         if (worst == 0) return
         associate (cr => model%geometry%corners)
            text = 'the BOUNDARY STRESS pulls the model in tension (largest principal stress '// &
                   trim(adjustl(fmt_real(s1, 10, 3)))//' at the boundary point at ('// &
                   trim(adjustl(fmt_real(cr%x(bnd%corner(worst)), 12, 5)))//', '// &
                   trim(adjustl(fmt_real(cr%y(bnd%corner(worst)), 12, 5)))//'); stresses are '// &
                   'positive in tension, manual Section 4.1) and its joints cannot hold it (tensile '// &
                   'strength JTENSILE '//trim(adjustl(fmt_real(tens, 10, 3)))
            if (tens == 0.0_wp) text = text//', the default'
            text = text//'): the blocks on the boundary are pulled off the model and fly apart; '// &
                   'a rock mass under a far-field load wants negative (compressive) BOUNDARY '// &
                   'STRESS, and a tension test wants joints with JTENSILE or blocks held by '// &
                   'velocities'
         end associate
      end associate
   end function boundary_pull_words

   !> The largest stress the weight makes at the foot of the model under
   !> GRAVITY: rho |g| H, rho the densest live block's material and H the
   !> model's height along g (weight_height); 0 without gravity.
   function weight_stress(model) result(s)
      type(model_t), intent(in) :: model
      real(wp) :: s
      real(wp) :: rho
      integer(ip) :: b
      rho = 0.0_wp
      associate (bl => model%geometry%blocks)
         do b = 1, bl%n
            if (bl%live(b)) rho = max(rho, model%materials%get(int(bl%material(b)), prop_density))
         end do
      end associate
      s = rho*norm2(model%gravity)*weight_height(model)
   end function weight_stress

   !> The model's height along GRAVITY's direction, from the live blocks'
   !> bounding boxes; 0 without gravity.
   function weight_height(model) result(h)
      type(model_t), intent(in) :: model
      real(wp) :: h
      real(wp) :: g, ex, ey, hmin, hmax
      integer(ip) :: b
      h = 0.0_wp
      g = norm2(model%gravity)
      if (.not. g > 0.0_wp) return
      ex = model%gravity(1)/g
      ey = model%gravity(2)/g
      hmin = huge(1.0_wp)
      hmax = -huge(1.0_wp)
      associate (bl => model%geometry%blocks)
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            ! the box's corners lowest and highest along (ex, ey)
            hmin = min(hmin, ex*merge(bl%xmin(b), bl%xmax(b), ex >= 0.0_wp) + &
                             ey*merge(bl%ymin(b), bl%ymax(b), ey >= 0.0_wp))
            hmax = max(hmax, ex*merge(bl%xmax(b), bl%xmin(b), ex >= 0.0_wp) + &
                             ey*merge(bl%ymax(b), bl%ymin(b), ey >= 0.0_wp))
         end do
      end associate
      if (hmax > hmin) h = hmax - hmin
   end function weight_height

   !> First CYCLE under GRAVITY: a zoned or SDEF material that its own
   !> weight would strain by more than 10 % (rho g H / E, E = 9 K G / (3 K +
   !> G), H the model's height) is almost always a deck whose units do not
   !> agree (manual Table 4-1): moduli in MPa with a density in kg/m3 strain
   !> it a thousand-million-fold. Found on a new user's deck (K 16667,
   !> G 12500, DENSITY 2700, GRAVITY 0 -9.81): the first steps stopped on
   !> Contact Overlap Too Great with no word of units.
   subroutine note_weight_strain(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      real(wp) :: gh, k, g, strain, worst
      integer(ip) :: b, m, mworst
      character(len=1000) :: line
      gh = norm2(model%gravity)*weight_height(model)
      if (.not. gh > 0.0_wp) return
      worst = 0.0_wp
      mworst = 0
      associate (bl => model%geometry%blocks)
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            if (bl%nzone(b) <= 0 .and. .not. bl%sdef(b)) cycle
            m = bl%material(b)
            k = model%materials%get(int(m), prop_bulk)
            g = model%materials%get(int(m), prop_shear)
            if (.not. (k > 0.0_wp .and. g > 0.0_wp)) cycle
            strain = model%materials%get(int(m), prop_density)*gh*(3.0_wp*k + g)/(9.0_wp*k*g)
            if (strain > worst) then
               worst = strain
               mworst = m
            end if
         end do
      end associate
      if (worst <= 0.1_wp) return
      write (line, '(a,i0,5a)') 'CYCLE: note: under its own weight material ', mworst, &
         ' would strain by rho g H / E = ', trim(adjustl(fmt_real(worst, 10, 3))), &
         ' over the model''s height H: are the units consistent? (manual Table 4-1: with moduli ', &
         'and stresses in MPa the density is in 10^6 kg/m3, 2.7E-3 for rock; in kPa, in 10^3 kg/m3)'
      call out%line(trim(line))
   end subroutine note_weight_strain

   !> First CYCLE of a model that carries initial stresses (INSITU: contact
   !> forces or zone stresses) and that no boundary condition holds (no
   !> BOUNDARY stress or load, no velocity, no FIX): the outer edges are
   !> free, so the model springs out and the stresses unload. A new user's
   !> SOLVE before any BOUNDARY (round 12, docs/closed_form.md) ran 600
   !> cycles and ended "nothing to balance ... or no load given?" though an
   !> INSITU stress of -5 MPa had been given: the note says where it went.
   subroutine note_stress_unheld(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer(ip) :: i, c, z
      logical :: stressed
      if (model_held(model)) return
      associate (geo => model%geometry, bnd => model%bound, ct => model%geometry%contacts, &
                 zn => model%geometry%zones)
         do i = 1, bnd%n
            if (bnd%fx(i) /= 0.0_wp .or. bnd%fy(i) /= 0.0_wp .or. bnd%dfx(i) /= 0.0_wp .or. &
                bnd%dfy(i) /= 0.0_wp .or. boundary_has_traction(bnd, i)) return
         end do
         stressed = .false.
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            if (ct%state%fn(c) > 0.0_wp) then
               stressed = .true.
               exit
            end if
         end do
         if (.not. stressed) then
            do z = 1, zn%n
               if (.not. zn%live(z)) cycle
               if (zn%sxx(z) /= 0.0_wp .or. zn%syy(z) /= 0.0_wp .or. zn%sxy(z) /= 0.0_wp) then
                  stressed = .true.
                  exit
               end if
            end do
         end if
      end associate
      if (.not. stressed) return
      call out%line('CYCLE: note: the model carries initial stresses (INSITU) and no boundary '// &
                    'condition holds them (no BOUNDARY stress or load, no velocity, no FIX): its '// &
                    'outer edges are free, so it springs out and the stresses unload; to keep the '// &
                    'field give BOUNDARY STRESS equal to it before cycling (manual Section 4.5, BOUNDARY)')
   end subroutine note_stress_unheld

   !> MSCALE PART tdel raises the masses of gridpoints too light for tdel
   !> (zones_prepare, viscous_fit_masses). In a dynamic run that slows the
   !> waves where it acts: Application D zoned finer at its printed
   !> MSCALE PART 1.5E-3 raised some gridpoints about 50-fold and its slip came
   !> out 0.076 to 0.012 m against a converged 0.06 (issue 21), silently.
   !> Each CYCLE says how many masses were raised, the largest factor and
   !> where, and the raised share of the grid's mass.
   subroutine note_mscale_part(model, zw, out, noted)
      type(model_t), intent(in) :: model
      type(zone_work_t), intent(in) :: zw
      type(output_t), intent(inout) :: out
      !> the count and factor last noted (a deck of many CYCLE commands)
      real(wp), intent(inout), optional :: noted(2)
      integer(ip) :: k, nraised, kmax
      real(wp) :: f, fmax, madd, mtot
      character(len=400) :: line
      character(len=24) :: pct
      if (.not. (model%mech%mscale .and. model%mech%mscale_part)) return
      nraised = 0
      kmax = 0
      fmax = 1.0_wp
      madd = 0.0_wp
      mtot = 0.0_wp
      associate (gp => model%geometry%gridpoints)
         do k = 1, gp%n
            if (.not. gp%live(k) .or. .not. gp%mass(k) > 0.0_wp) cycle
            mtot = mtot + gp%mass(k)
            if (zw%m_in(k) <= gp%mass(k)*(1.0_wp + 1.0e-9_wp)) cycle
            nraised = nraised + 1
            madd = madd + zw%m_in(k) - gp%mass(k)
            f = zw%m_in(k)/gp%mass(k)
            if (f > fmax) then
               fmax = f
               kmax = k
            end if
         end do
         if (nraised == 0) return
         if (present(noted)) then
            if (noted(1) == real(nraised, wp) .and. abs(noted(2) - fmax) <= 1.0e-2_wp*fmax) return
            noted = [real(nraised, wp), fmax]
         end if
         write (line, '(a,i0,a,i0,a,f0.1,7a)') 'CYCLE: note: MSCALE PART raised the masses of ', &
            nraised, ' of ', count(gp%live(1:gp%n)), ' gridpoints, at most ', &
            min(fmax, 1.0e9_wp), '-fold (gridpoint ', trim(itoa(kmax)), &
            ' at (', trim(adjustl(fmt_real(gp%x(kmax), 11, 4))), ',', &
            trim(adjustl(fmt_real(gp%y(kmax), 11, 4))), ')), adding '
      end associate
      write (pct, '(f0.1)') 100.0_wp*madd/max(mtot, tiny(1.0_wp))
      line = trim(line)//' '//trim(pct)//' % to the grid''s mass: a static answer does not depend on it, waves in a '// &
             'dynamic run are slowed where it acts (a smaller MSCALE PART time step raises fewer)'
      call out%line(trim(line))
   end subroutine note_mscale_part

   !> First CYCLE of a zoned model held by fixed boundary forces (SET -FUP
   !> stresses, XLOAD / YLOAD) with no prescribed gridpoint velocity and no
   !> FIXed block: a note. Fixed forces keep their direction (the manual's
   !> KBDFX/KBDFY), so a free body under compression has a negative
   !> stiffness against rotation: any asymmetry starts a rigid rotation that
   !> grows (verification E1 under -FUP past 4000 cycles). Under DAMP AUTO
   !> the turn hold (engine_turn) takes that turn out; the note then names
   !> the drift only.
   subroutine note_unrestrained(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer(ip) :: n
      character(len=*), parameter :: head = 'CYCLE: note: no gridpoint velocity is '// &
                                     'prescribed and no block is fixed; the model is held by '// &
                                     'fixed boundary forces (SET -FUP, XLOAD, YLOAD), which keep '// &
                                     'their direction, so it can drift'
      n = model%bound%n
      if (n == 0) return
      if (all(model%bound%fx(1:n) == 0.0_wp .and. model%bound%fy(1:n) == 0.0_wp .and. &
              model%bound%dfx(1:n) == 0.0_wp .and. model%bound%dfy(1:n) == 0.0_wp)) return
      if (model_held(model)) return
      if (turn_hold_wanted(model)) then
         call out%line(head//' (its turn as one body is taken out under DAMP AUTO or LOCAL; '// &
                       'fix a point for long runs; docs/zones.md)')
      else
         call out%line(head//' and, under compression, rotate (fix a point and a direction '// &
                       'for long runs; docs/zones.md)')
      end if
   end subroutine note_unrestrained

   !> A CYCLE of a model that nothing holds in place (no FIXed block, no
   !> prescribed or viscous boundary): when the boundary forces, the loads and
   !> the weight do not add up to zero, the whole model accelerates, and no
   !> damping stops it. A note names the net force against the weight (found
   !> on a new user's model: gravity and a uniform BOUND STRESS, no YGRAD;
   !> SOLVE ran its 100 000 cycles while the blocks fell 7 m). Checked at
   !> every CYCLE command, not only the first: a DELETE under gravity takes
   !> the weight of the rock it removes out of a balance the boundary
   !> stresses keep, and the model then rises as one body (a tunnel in a
   !> stress-bounded block: SOLVE never balanced). A note is given once for
   !> one imbalance (`noted`, the CYCLE commands' report), again when the net
   !> force changes; without a report, only at the model's first step. A
   !> model held in one direction only (XVEL rollers on its sides, a FIX
   !> range no block centroid lies in) gets the note for the other: a new
   !> user's model fell 525 m under gravity while SOLVE ran 200 000 cycles.
   subroutine note_net_force(model, out, tol, noted, unheld)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      !> the size of a net force noted [N] (0 when the model is held): the
      !> turn hold (engine_turn) balances a smaller one
      real(wp), intent(out) :: tol
      real(wp), intent(inout), optional :: noted(2)
      !> the net force is above the tolerance in a direction nothing holds:
      !> the model can never balance (SOLVE stops before it starts)
      logical, intent(out), optional :: unheld
      integer(ip) :: i, b
      real(wp) :: fx, fy, wx, wy, tfx, tfy, tdfx, tdfy, fsum, m, w, nfree
      logical :: heldx, heldy
      character(len=1) :: free_dir
      character(len=640) :: line
      associate (geo => model%geometry, bnd => model%bound, bl => model%geometry%blocks)
         tol = 0.0_wp
         if (present(unheld)) unheld = .false.
         if (bl%n == 0) return
         ! held by a FIXed block, a gridpoint velocity, the BE far field or the
         ! free field (model_held); boundary velocities are counted per direction below
         if (any(bl%fixed(1:bl%n) .and. bl%live(1:bl%n))) return
         if (geo%gridpoints%n > 0) then
            if (any(geo%gridpoints%vfix(1:geo%gridpoints%n) /= 0 .and. &
                    geo%gridpoints%live(1:geo%gridpoints%n))) return
         end if
         if (model%be%ne > 0 .or. model%ffield%on) return
         if (bnd%n > 0) then
            if (any(bnd%ff(1:bnd%n) /= 0)) return
         end if
         fx = 0.0_wp
         fy = 0.0_wp
         fsum = 0.0_wp
         ! directions a prescribed or viscous boundary holds
         heldx = any(bnd%ix(1:bnd%n) == bc_velocity .or. bnd%ix(1:bnd%n) == bc_viscous .or. &
                     iand(bnd%vis(1:bnd%n), vis_x) /= 0)
         heldy = any(bnd%iy(1:bnd%n) == bc_velocity .or. bnd%iy(1:bnd%n) == bc_viscous .or. &
                     iand(bnd%vis(1:bnd%n), vis_y) /= 0)
         if (heldx .and. heldy) return
         do i = 1, bnd%n
            if (.not. geo%corners%live(bnd%corner(i))) cycle
            if (.not. bl%live(geo%corners%block(bnd%corner(i)))) cycle
            call boundary_traction_force(bnd, geo, i, tfx, tfy, tdfx, tdfy)
            tfx = bnd%xmul(i)*(bnd%fx(i) + tfx + bnd%dfx(i) + tdfx)
            tfy = bnd%ymul(i)*(bnd%fy(i) + tfy + bnd%dfy(i) + tdfy)
            fx = fx + tfx
            fy = fy + tfy
            fsum = fsum + hypot(tfx, tfy)
         end do
         wx = 0.0_wp
         wy = 0.0_wp
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            m = model%materials%get(int(bl%material(b)), prop_density)*bl%area(b)
            wx = wx + m*model%gravity(1)
            wy = wy + m*model%gravity(2)
            fx = fx + bl%lx(b)
            fy = fy + bl%ly(b)
            fsum = fsum + hypot(bl%lx(b), bl%ly(b))
         end do
         w = hypot(wx, wy)
         ! out of balance by more than 0.05 % of the weight (a YGRAD rounded
         ! to three digits, 2.45e4 for 2500 x 9.81, is 0.1 % and keeps SOLVE
         ! from balancing; a 6 m tunnel deleted from a 40 m square is 1.8 %),
         ! or 0.1 % of the boundary forces' magnitudes when nothing weighs
         if (w > 0.0_wp) then
            w = 5.0e-4_wp*w
         else
            w = 1.0e-3_wp*fsum
         end if
         if (heldx .or. heldy) then
            ! held in one direction only (rollers on the sides, say, and
            ! nothing under the base): the other must balance by itself
            if (heldx) then
               nfree = abs(fy + wy)
            else
               nfree = abs(fx + wx)
            end if
            if (.not. nfree > w) then
               if (present(noted)) noted = 0.0_wp
               return
            end if
            if (present(unheld)) unheld = .true.
            if (present(noted)) then
               if (hypot(fx + wx - noted(1), fy + wy - noted(2)) <= 1.0e-2_wp*nfree) return
               noted = [fx + wx, fy + wy]
            else if (model%mech%step > 0) then
               return
            end if
            free_dir = merge('y', 'x', heldx)
            write (line, '(9a)') 'CYCLE: note: nothing holds the model in ', free_dir, &
               ' (no FIX, no ', merge('Y', 'X', heldx), 'VEL or viscous boundary in ', free_dir, &
               ') and its loads do not balance in ', free_dir, ': boundary forces and loads ('
            line = trim(line)//trim(fmt_real(fx, 11, 4))//', '//trim(fmt_real(fy, 11, 4))// &
                   ') N, weight ('//trim(fmt_real(wx, 11, 4))//', '//trim(fmt_real(wy, 11, 4))// &
                   ') N: the whole model will accelerate as one body in '//free_dir// &
                   '; hold it (BOUND '//merge('Y', 'X', heldx)//'VEL 0 on the base''s corners, '// &
                   'FIX a block) '// &
                   'or give the boundary stress the gradient of the weight'
            call out%line(trim(line))
            return
         end if
         tol = w
         if (hypot(fx + wx, fy + wy) <= w .or. hypot(fx + wx, fy + wy) <= 0.0_wp) then
            if (present(noted)) noted = 0.0_wp
            return
         end if
         if (present(unheld)) unheld = .true.
         ! this imbalance was noted already (a deck of many CYCLE commands)
         if (present(noted)) then
            if (hypot(fx + wx - noted(1), fy + wy - noted(2)) <= 1.0e-2_wp*hypot(fx + wx, fy + wy)) return
            noted = [fx + wx, fy + wy]
         else if (model%mech%step > 0) then
            return
         end if
         write (line, '(9a)') 'CYCLE: note: nothing holds the model in place (no FIX, no ', &
            'velocity or viscous boundary) and its loads do not balance: boundary forces and ', &
            'loads (', trim(fmt_real(fx, 11, 4)), ', ', trim(fmt_real(fy, 11, 4)), &
            ') N, weight (', trim(fmt_real(wx, 11, 4)), ', '
         line = trim(line)//' '//trim(fmt_real(wy, 11, 4))//') N: the whole model will '// &
                'accelerate as one body; give the boundary stress the gradient of the weight '// &
                '(YGRAD = density x g) or hold the base (BOUND YVEL 0, FIX); a DELETE under '// &
                'gravity takes the weight of the rock it removes out of the balance'
         call out%line(trim(line))
      end associate
   end subroutine note_net_force

   !> DAMP AUTO after a load change on a zoned model (model_mechanics
   !> damping_load_changed; an extension beyond UDEC manual (ICG1.5, 1989),
   !> Section 4.5, DAMP, docs/mechanics.md). The manual's rule finds alpha from
   !> the kinetic energy's changes; at rest it drifts down (to 13 1/s on a
   !> jointed zoned tunnel) and a load given at once rang to 1.66 times its
   !> static change. Each step after the load estimates the frequency of the
   !> mode that moves from the step's own motion, the Rayleigh quotient of its
   !> velocity w^2 = v.K v / v.M v with K v dt = -dF, the change of the force
   !> sums over the step (core_motion kvv, mvv; as adaptive dynamic relaxation
   !> does), and sets alpha = 2 w, critical damping for that mode. After the
   !> load the motion spreads from the loaded boundary and w falls, about as
   !> 1 / t while the front travels, to the slow mode the load drives; the
   !> probe's clock (mech%probe_time) starts again each time w falls below
   !> probe_fall of the value it started from (mech%probe_wref), and once it
   !> passes probe_span / w (that mode critically damped has come within
   !> (1 + 8) e^-8 = 0.3 % of its new rest) the manual's rule goes on from
   !> alpha = 2 w. A step whose motion gives no estimate (at rest, or v.K v
   !> <= 0 while joints slide) keeps the last one.
   subroutine damping_probe(mech, mot, measured)
      type(mechanics_t), intent(inout) :: mech
      type(motion_result_t), intent(in) :: mot
      logical, intent(in) :: measured
      real(wp), parameter :: probe_span = 8.0_wp, probe_fall = 0.95_wp
      mech%probe_time = mech%probe_time + mech%dt
      if (measured .and. mot%kvv > 0.0_wp .and. mot%mvv > 0.0_wp) then
         mech%probe_w = sqrt(mot%kvv/(mech%dt*mot%mvv))
         mech%auto_alpha = min(max(2.0_wp*mech%probe_w, 1.0e-6_wp/mech%dt), 1.0_wp/mech%dt)
         if (.not. mech%probe_w >= probe_fall*mech%probe_wref) then
            mech%probe_wref = mech%probe_w
            mech%probe_time = 0.0_wp
         end if
      end if
      if (mech%probe_w > 0.0_wp .and. mech%probe_time*mech%probe_w > probe_span) mech%probe_time = -1.0_wp
   end subroutine damping_probe

   !> Rayleigh damping constants (module header): mass-proportional alpha
   !> [1/s] and stiffness-proportional beta [s] (into the contact workspace).
   subroutine damping_constants(model, cw, alpha)
      type(model_t), intent(in) :: model
      type(contact_work_t), intent(inout) :: cw
      real(wp), intent(out) :: alpha
      real(wp) :: w
      alpha = 0.0_wp
      cw%beta = 0.0_wp
      associate (mech => model%mech)
         if (mech%damping /= damping_rayleigh .or. mech%rayleigh_freq <= 0.0_wp) return
         w = 2.0_wp*pi*mech%rayleigh_freq
         if (mech%rayleigh_mass .and. mech%rayleigh_stiff) then
            alpha = mech%rayleigh_fcrit*w
            cw%beta = mech%rayleigh_fcrit/w
         else if (mech%rayleigh_mass) then
            alpha = 2.0_wp*mech%rayleigh_fcrit*w
         else
            cw%beta = 2.0_wp*mech%rayleigh_fcrit/w
         end if
      end associate
   end subroutine damping_constants

   !> The stiffest joint material (JKN, JKS) [stress/length] and point
   !> contact material (KN, KS) [force/length] of the PROPERTY table.
   subroutine joint_stiffness_max(model, kmat, kmax)
      type(model_t), intent(in) :: model
      real(wp), intent(out) :: kmat, kmax
      integer :: j
      kmat = 0.0_wp
      kmax = 0.0_wp
      do j = 1, model%materials%nmat
         kmat = max(kmat, model%materials%get(j, prop_jkn), model%materials%get(j, prop_jks))
         kmax = max(kmax, model%materials%get(j, prop_kn), model%materials%get(j, prop_ks))
      end do
   end subroutine joint_stiffness_max

   !> Stable time step (see module header).
   !> The time step: blocks and contacts (FRACTION fb), zones and SDEF
   !> blocks with their joints (fz; engine_sdef's sdef_timestep), reduced
   !> for stiffness-proportional damping, and at most the stable step of the
   !> viscous boundaries' dashpots (zones_viscous).
   real(wp) function cycle_timestep(model, wk, unbound) result(dt)
      type(model_t), intent(in) :: model
      type(cycle_work_t), intent(in) :: wk
      logical, intent(out), optional :: unbound
      real(wp) :: mmin, kmax, kmat, dtc, lam, dtz, kforce, kunit, dtsz
      integer(ip) :: b
      associate (geo => model%geometry)
         ! contacts whose stiffness depends on their state, with headroom
         call contact_state_stiffness(wk%cw, geo, kforce, kunit)
         ! stiffest joint material [stress/length] and point contact [force/length]
         call joint_stiffness_max(model, kmat, kmax)
         mmin = huge(1.0_wp)
         dtc = huge(1.0_wp)
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (geo%blocks%fixed(b) .or. wk%mw%m_in(b) <= 0.0_wp) cycle
            if (geo%blocks%fdef(b)) cycle      ! bounded by its gridpoints below
            mmin = min(mmin, wk%mw%m_in(b))
            ! a contact this block may make: the stiffest material over its size
            if (kmat > 0.0_wp) &
               dtc = min(dtc, 2.0_wp*sqrt(wk%mw%m_in(b)/(kmat*sqrt(geo%blocks%area(b)))))
         end do
         kmax = max(kmax, contact_stiffness_max(wk%cw, geo), state_headroom*kforce)
         if (mmin < huge(1.0_wp) .and. kmax > 0.0_wp) dtc = min(dtc, 2.0_wp*sqrt(mmin/kmax))
         ! SDEF blocks: their rigid modes are bounded above as rigid blocks
         ! (fb); all six modes together with the joints at their corners
         ! (sdef_timestep), a deformation like a zone's, take fz
         dtsz = huge(1.0_wp)
         if (wk%mw%sd%active) dtsz = sdef_timestep(geo, wk%mw%sd, wk%mw%m_in, wk%mw%i_in, kmat, kmax)
         dtz = min(zones_timestep(geo, wk%zw), dtsz)
         ! the gridpoints' bound counts the joints at the stiffest JKN / JKS
         ! (zones_prepare); a state-dependent joint stiffer than that scales
         ! it (conservatively: as if the whole bound were joint stiffness)
         if (dtz < huge(1.0_wp) .and. state_headroom*kunit > kmat .and. kmat > 0.0_wp) &
            dtz = dtz*sqrt(kmat/(state_headroom*kunit))
         ! structure nodes count with the gridpoints (FRACTION fz), unless
         ! MSCALE makes them heavier to fit the step (cycle_prepare)
         if (wk%sw%active .and. .not. model%mech%mscale) &
            dtz = min(dtz, structure_timestep(model%structures, wk%sw))
         ! reinforcement springs on blocks and gridpoints (reinforce_mechanics)
         if (wk%sw%rw%active) then
            dtc = dt_combined(dtc, wk%sw%rw%dt_block)
            dtz = dt_combined(dtz, wk%sw%rw%dt_gp)
         end if
         if (dtc == huge(1.0_wp) .and. dtz == huge(1.0_wp)) then
            ! nothing free or nothing stiff: any step will do; keep the old one
            if (present(unbound)) unbound = .true.
            dt = model%mech%dt
            if (dt <= 0.0_wp) dt = 1.0_wp
            dt = min(dt, wk%vw%dt_max, wk%vw%dt_ffield)
            return
         end if
         if (present(unbound)) unbound = .false.
         dt = huge(1.0_wp)
         if (dtc < huge(1.0_wp)) dt = model%mech%frac_block*dtc
         if (dtz < huge(1.0_wp)) dt = min(dt, zone_fraction(model%mech)*dtz)
         dtc = min(dtc, dtz)
         if (wk%cw%beta > 0.0_wp) then
            lam = wk%cw%beta/dtc
            dt = dt*(sqrt(1.0_wp + lam*lam) - lam)
         end if
         dt = min(dt, wk%vw%dt_max, wk%vw%dt_ffield)
         ! MSCALE PART tdel: the step is tdel (manual Section 4.5: scaling
         ! "to achieve time-step tdel"); where no mass needed raising the
         ! model's own step was larger, and a dynamic stage of n cycles
         ! covered more time than n tdel (accur, session 40: 6.8e-4 s asked,
         ! a larger step run)
         if (wk%zw%active .and. model%mech%mscale .and. model%mech%mscale_part .and. &
             model%mech%mscale_tdel > 0.0_wp) dt = min(dt, model%mech%mscale_tdel)
      end associate
   contains
      !> Two bounds of the same bodies: 1 / dt^2 adds as the stiffness does.
      pure real(wp) function dt_combined(a, b) result(c)
         real(wp), intent(in) :: a, b
         if (b == huge(1.0_wp)) then
            c = a
         else if (a == huge(1.0_wp)) then
            c = b
         else
            c = 1.0_wp/sqrt(1.0_wp/(a*a) + 1.0_wp/(b*b))
         end if
      end function dt_combined
   end function cycle_timestep

   !> The cause of a "Contact Overlap Too Great" at contact c (UDEC manual
   !> (ICG1.5, 1989), Section 5.3) as far as the contact shows it: how much it
   !> closed in the failing step, its normal stress, and the most normal
   !> stress change its joint takes within the tolerance, JKN x OVTOL (a soft
   !> joint under a bigger load fails however small the step: 1e5 Pa/m and
   !> OVTOL 0.05 m take 5e3 Pa, a metre of rock weighs 2.6e4). A contact that
   !> closes by less than a tenth of OVTOL per step is squeezed steadily by
   !> its load; a faster one may be a numerical instability as well. Only the
   !> model's last good state is read (the step is undone). `ovtol` is the
   !> contact's own tolerance, `base` the model's OVTOL (they differ where
   !> the contact's rounded corners allow more, contact_overlap_limit).
   !> Why the geometry is lost past that tolerance (overlap_bound_words),
   !> and where `step_load` (step_load_on_unloaded_joints at the CYCLE's
   !> start) the step load's cause and remedy.
   function overlap_cause(model, c, grow, ovtol, base, step_load, pull) result(text)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: grow, ovtol, base
      logical, intent(in) :: step_load
      !> boundary_pull_words at the CYCLE's start: '' when the boundary does not pull
      character(len=*), intent(in) :: pull
      character(len=:), allocatable :: text
      character(len=:), allocatable :: tolname
      real(wp) :: sn, kn
      associate (ct => model%geometry%contacts)
         sn = 0.0_wp
         if (ct%length(c) > 0.0_wp) sn = ct%state%fn(c)/ct%length(c)
         kn = 0.0_wp
         if (ct%jmat(c) > 0) kn = model%materials%get(int(ct%jmat(c)), prop_jkn)
         text = '; it closed by '//trim(adjustl(fmt_real(grow, 10, 3)))//' in the last step'
         if (grow < 0.1_wp*ovtol) text = text//', steadily'
         if (ct%length(c) > 0.0_wp) then
            text = text//' (normal stress '//trim(adjustl(fmt_real(sn, 10, 3)))//')'
         else
            ! a contact of no length (a corner against a corner or at a
            ! joint's end) carries a force but no stress
            text = text//' (normal force '//trim(adjustl(fmt_real(ct%state%fn(c), 10, 3)))// &
                   ' on a contact of zero length)'
         end if
         tolname = 'OVTOL'
         if (ovtol > base) tolname = 'its tolerance (from its rounded corners, at most 2 ROUND)'
         text = text//'; within the tolerance its joint takes a normal stress change of at most '// &
                'JKN x '//tolname//' = '//trim(adjustl(fmt_real(kn*ovtol, 10, 3)))
         if (grow < 0.1_wp*ovtol) then
            text = text//' (manual Section 5.3: a joint normal stiffness too low for the '// &
                   'loads, or a rounding too small: raise JKN or ROUND, whose half is the '// &
                   'tolerance, or SET OVTOL)'
         else
            text = text//' (manual Section 5.3: a joint normal stiffness too low for the '// &
                   'loads, a rounding too small, or a time step too large for the damping '// &
                   'or the dilation)'
         end if
         text = text//overlap_bound_words(model, c, base)
         text = text//acute_tip_remedy(model%geometry, c)
         if (len(pull) > 0) then
            ! the tension is the cause; JKN, ROUND and INSITU do not help
            text = '; '//pull//text
         else if (step_load) then
            text = text//'; '//step_load_words
         end if
      end associate
   end function overlap_cause

   !> What the tolerance of contact c (contact_overlap_bound; `ovtol` the
   !> model's OVTOL) stands for, so that the stop says why the contact's
   !> geometry is lost past it (UDEC manual (ICG1.5, 1989), Section 3.3,
   !> Fig. 3-3d: the normal of two rounded corners is the line of their
   !> circle centres): '' for OVTOL itself.
   function overlap_bound_words(model, c, ovtol) result(text)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: ovtol
      character(len=:), allocatable :: text
      real(wp) :: limit, measure
      integer :: which
      character(len=4) :: share
      call contact_overlap_bound(model%geometry, c, ovtol, model%mech%ovtol > 0.0_wp, limit, which, &
                                 measure)
      select case (which)
      case (overlap_bound_radii)
         text = '; its tolerance is half the overlap '//trim(adjustl(fmt_real(measure, 10, 3)))// &
                ' (the sum of its corners'' rounding radii) at which their circle centres meet and '// &
                'the normal, their line (manual Section 3.3, Fig. 3-3d), is lost: past the half '// &
                'the turning of the normal under its force is a spring stiffer than the contact, '// &
                'whose stiffness sets the time step'
      case (overlap_bound_switch)
         write (share, '(f4.2)') switch_fraction
         text = '; its tolerance is '//share//' of the overlap '//trim(adjustl(fmt_real(measure, 10, 3)))// &
                ' (the sum of the rounding radii of its corner and of its edge''s nearer end) past '// &
                'which its switch to a corner-corner contact at that end loses the gap and the '// &
                'normal (manual Section 3.3, Fig. 3-3d)'
      case (overlap_bound_round)
         text = '; its tolerance is 2 ROUND, the width of a corner''s rounded zone (its arc runs from '// &
                'ROUND before the vertex to ROUND after it, manual Section 3.3): deeper, the corner '// &
                'is pressed past its rounding into the facing block'
      case (overlap_bound_edge)
         text = '; its tolerance is a quarter of the shortest edge at the contact ('// &
                trim(adjustl(fmt_real(measure, 10, 3)))//'): deeper, the corner reaches toward the '// &
                'facing block''s other edges, and which edge it touches is no longer defined (a '// &
                'sliver of rock at a joint''s end or the opening)'
      case default
         text = ''
      end select
   end function overlap_bound_words

   !> Where contact c's corner (either block's, for a corner-corner contact)
   !> is an acute tip, under acute_tip_deg degrees, the words naming it and
   !> the remedy; '' otherwise. Two wedges pressed tip to tip meet on a
   !> contact of no length whose rounded corners carry the whole load: the
   !> manual's remedy (Section 5.3, "increase the rounding length at the
   !> start of the problem ... blocks with very acute angles") is a larger
   !> ROUND, or a joint moved so that the tip is not made.
   function acute_tip_remedy(geo, c) result(text)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      character(len=:), allocatable :: text
      real(wp), parameter :: acute_tip_deg = 30.0_wp
      integer(ip) :: k, q, sharp
      real(wp) :: theta, best
      integer(ip) :: cand(2)
      character(len=16) :: degrees
      text = ''
      cand = 0
      if (geo%contacts%kind(c) /= 3) cand(1) = contact_corner1(geo%contacts, c)
      if (geo%contacts%kind(c) /= 2) cand(2) = contact_corner2(geo%contacts, c)
      sharp = 0
      best = acute_tip_deg
      do q = 1, 2
         k = cand(q)
         if (k <= 0) cycle
         theta = corner_angle_deg(geo, k)
         if (theta < best) then
            best = theta
            sharp = k
         end if
      end do
      if (sharp == 0) return
      write (degrees, '(f0.1)') best
      text = '; block '//itoa(geo%corners%block(sharp))//'''s corner at ('// &
             trim(adjustl(fmt_real(geo%corners%x(sharp), 12, 5)))//', '// &
             trim(adjustl(fmt_real(geo%corners%y(sharp), 12, 5)))//') is an acute tip of '// &
             trim(degrees)//' degrees, whose rounded corner carries '// &
             'the contact alone: a larger ROUND at the start of the problem (manual Section 5.3, '// &
             'for blocks with very acute angles), or a JSET / CRACK moved so that the tip is '// &
             'not made, removes it'
   end function acute_tip_remedy

   !> Interior angle (degrees) of corner k of its clockwise block; 360 minus
   !> the turn for a re-entrant corner.
   real(wp) function corner_angle_deg(geo, k) result(theta)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: k
      real(wp) :: ux, uy, vx, vy
      associate (cr => geo%corners)
         ux = cr%x(cr%prev(k)) - cr%x(k)
         uy = cr%y(cr%prev(k)) - cr%y(k)
         vx = cr%x(cr%next(k)) - cr%x(k)
         vy = cr%y(cr%next(k)) - cr%y(k)
      end associate
      theta = atan2(abs(ux*vy - uy*vx), ux*vx + uy*vy)*180.0_wp/pi
      ! clockwise: a convex corner turns right (u x v > 0 from prev to next)
      if (ux*vy - uy*vx < 0.0_wp) theta = 360.0_wp - theta
   end function corner_angle_deg

   !> Remember the stiffness of the state-dependent contacts the step was
   !> just computed for (cycle_timestep adds state_headroom).
   subroutine note_state_stiffness(cw, geo)
      type(contact_work_t), intent(inout) :: cw
      type(geometry_t), intent(in) :: geo
      real(wp) :: kforce, kunit
      call contact_state_stiffness(cw, geo, kforce, kunit)
      cw%kstate_dt = state_headroom*kforce
   end subroutine note_state_stiffness

   !> A JCONS 3 joint whose stress-dependent stiffness (JKN sigma_n^JEN,
   !> JKS sigma_n^JES) is a million times its JKN / JKS sets a time step so
   !> small that the CYCLE barely advances the time (JES = 50: steps of
   !> 1e-29 s, issue 20): say so before cycling.
   subroutine note_stiff_state(model, cw, ncycles, out)
      type(model_t), intent(in) :: model
      type(contact_work_t), intent(in) :: cw
      integer(i8), intent(in) :: ncycles
      type(output_t), intent(inout) :: out
      real(wp) :: kforce, kunit, kmat, kmax
      call contact_state_stiffness(cw, model%geometry, kforce, kunit)
      call joint_stiffness_max(model, kmat, kmax)
      if (kmat <= 0.0_wp .or. .not. kunit > 1.0e6_wp*kmat) return
      call out%line('CYCLE: note: a JCONS 3 joint''s stress-dependent stiffness (JKN sn^JEN, '// &
                    'JKS sn^JES) is '//trim(format_real(kunit))//', more than a million times '// &
                    'JKN / JKS: the time step is '//trim(format_real(model%mech%dt))// &
                    ' and these cycles advance the time by only '// &
                    trim(format_real(model%mech%dt*real(ncycles, wp))))
   end subroutine note_stiff_state

   !> CYCLE n: execute n steps. Progress every 10 steps (or HIST NCYC) and a
   !> summary line go to `out` (on a terminal the rows are replaced by one
   !> progress line, core_progress). With `solve` (SOLVE), the force ratio
   !> (cycle_force_ratio) is measured at every row and the loop ends when it
   !> is below solve%ratio_limit. A numerical failure undoes the failing step
   !> and returns an error naming the contact or block and its position.
   !> Each step runs the stages of stage_list (engine_stages) in order; their
   !> wall time goes to `report` when given (PRINT CYCLE).
   subroutine cycle_run(model, ncycles, out, error, report, solve, searched)
      type(model_t), intent(inout) :: model
      integer(i8), intent(in) :: ncycles
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      type(cycle_report_t), intent(inout), optional :: report
      type(solve_t), intent(inout), optional :: solve
      !> the caller's geometry_refresh searched the whole model (cycle_prepare)
      logical, intent(in), optional :: searched
      type(progress_t) :: progress
      logical :: converged
      real(wp) :: ratio
      type(cycle_work_t) :: wk
      type(rigid_velocity_t) :: rvw
      integer(i8) :: n, every, t0, t1, rate, step0, ts0, ts1, done
      integer(i8), allocatable :: ticks(:)
      logical :: interrupted, slow_flow_noted, overlap_noted
      logical :: step_load               !< this CYCLE loads joints that carry no stress
      !> BOUNDARY STRESS pulling beyond the joints' tensile strength (boundary_pull_words)
      character(len=:), allocatable :: pull
      integer(ip) :: bad, ub, nnew, nbroken, k, ov_over
      real(wp) :: alpha, margin, ovtol, wall, setup
      real(wp) :: dpmax, ov_bad, ov_limit, ovscan
      type(motion_result_t) :: mot      !< the step's motion results (motion_add)
      real(wp) :: turn_w, drift_w, turn_taken, drift_taken, net_tol
      integer(i8) :: nrun
      logical :: unheld
      real(wp), allocatable :: hv(:)
      real(wp) :: aloc                   !< DAMP LOCAL's alpha (0 under other damping)
      logical :: probing                 !< this step measures its motion (damping_probe)
      integer, allocatable :: stages(:)
      character(len=240) :: line
      logical :: geometric, failed
      integer :: i
      call system_clock(t0, rate)
      net_tol = 0.0_wp
      interrupted = .false.
      converged = .false.
      ratio = -1.0_wp
      slow_flow_noted = .false.
      overlap_noted = .false.
      call cycle_prepare(model, wk, error, searched)
      if (allocated(error)) return
      stages = stage_list(model)
      ! without the stage no boundary follows a history: XHIS / YHIS read 1
      if (.not. any(stages == stage_boundaries)) then
         model%mech%fxhis = 1.0_wp
         model%mech%fyhis = 1.0_wp
      end if
      if (any(stages == stage_block_velocity)) &
         call rigid_velocity_build(model%bound, model%geometry, rvw)
      ! the column's force sums from its state and the base conditions as
      ! they are now (FFIELD may have changed them since the last CYCLE)
      if (any(stages == stage_ffield)) &
         call ffield_column_forces(model%ffield, wk%ffw, model%bound, model%mech%time, 0_i8, &
                                   ncycles)
      allocate (ticks(size(stages)))
      ticks = 0_i8
      associate (geo => model%geometry, mech => model%mech, hist => model%hist)
         margin = contact_margin(geo)
         ovtol = mech%ovtol
         if (ovtol <= 0.0_wp) ovtol = 0.5_wp*geo%round
         ! the corner copies of the rigid step are skipped when it cannot fail
         ! after moving them: a CYCLE whose only failure after the motion is
         ! a contact overlap, checked every step (engine_rigid motion_work_t)
         wk%mw%ovtol = ovtol
         ! the set-up's scan measured every contact's overlap: the first step
         ! needs no copies when they are all within the screen
         wk%mw%safe = wk%scan_overlap <= overlap_screen*ovtol
         wk%mw%may_skip = max(1_ip, mech%nupcon) == 1 .and. .not. any(stages == stage_sdef .or. &
                          stages == stage_gridpoint_motion .or. stages == stage_structure_motion &
                          .or. stages == stage_fluid .or. stages == stage_ffield .or. &
                          stages == stage_reinforcement .or. stages == stage_block_velocity)
         allocate (hv(max(1, hist%n)))
         every = 10
         if (hist%n > 0) every = max(1_i8, int(hist%ncyc, i8))
         ! adaptive damping starts at the highest contact frequency
         ! sqrt(k_max/m_min) = 2 fb / dt (half-critical for that mode)
         if (mech%damping == damping_auto .and. mech%auto_alpha <= 0.0_wp) &
            mech%auto_alpha = 2.0_wp*mech%frac_block/mech%dt
         ! a load change's probe (damping_probe) only on zones whose law is
         ! elastic: where they yield the answer depends on the path, and the
         ! probe's quasi-static one moved verification.closed_forms_salencon
         ! (psi 20) from +0.28 % to -2.37 % of its closed form (tolerance 2 %)
         if (mech%probe_time >= 0.0_wp .and. .not. (wk%zw%active .and. wk%zw%elastic_law)) &
            mech%probe_time = -1.0_wp
         ! after a static load change (damping_load_changed): its upper bound
         if (mech%damping == damping_auto .and. mech%dt > 0.0_wp) &
            mech%auto_alpha = min(mech%auto_alpha, 1.0_wp/mech%dt)
         ! A model that has never stepped has no force sums yet: forces are summed
         ! at the end of a step and move the model at the start of the next, so
         ! the first step would see gravity alone and a model put in equilibrium
         ! by INSITU would drop g dt and slip on its joints. Sum them once from
         ! the state as it is, with the velocities held at zero for that pass
         ! so the contact and zone passes add no increment and only assemble.
         if (ncycles > 0 .and. mech%step == 0) &
            call assemble_initial_forces(model, wk, ncycles, stages)
         if (model%bound%n > 0) &
            call boundary_cycle_start(model%bound, geo, &
                                      stage_args_t(time=mech%time, ncycles=ncycles))
         if (wk%vw%n > 0 .and. mech%dt >= wk%vw%dt_max .and. .not. (mech%mscale .and. &
             mech%mscale_part .and. wk%vw%dt_max >= mech%mscale_tdel*(1.0_wp - 1.0e-9_wp))) then
            write (line, '(3a)') 'CYCLE: note: the viscous boundary limits the time step '// &
               'to ', fmt_real(mech%dt, 11, 4), &
               ' (the stable step of its dashpots, mass / (rho c L)); '// &
               'a far-field material much stiffer or denser than the model costs steps'
            call out%line(trim(line))
         end if
         if (ncycles > 0 .and. mech%step == 0 .and. wk%zw%active .and. model%bound%n > 0) &
            call note_unrestrained(model, out)
         if (ncycles > 0 .and. mech%step == 0) call note_weight_strain(model, out)
         if (ncycles > 0 .and. mech%step == 0) call note_stress_unheld(model, out)
         step_load = .false.
         pull = ''
         if (ncycles > 0) pull = boundary_pull_words(model)
         ! a pulled model is not a step load of compression: INSITU does not hold it
         if (ncycles > 0 .and. len(pull) == 0) step_load = step_load_on_unloaded_joints(model)
         if (ncycles > 0 .and. mech%step == 0 .and. len(pull) > 0) &
            call out%line('CYCLE: note: '//pull)
         if (ncycles > 0 .and. mech%step == 0) call note_overlap_headroom(model, ovtol, step_load, out)
         if (ncycles > 0 .and. wk%zw%active) then
            if (present(report)) then
               call note_mscale_part(model, wk%zw, out, report%mscale_noted)
            else
               call note_mscale_part(model, wk%zw, out)
            end if
         end if
         unheld = .false.
         if (ncycles > 0) then
            if (present(report)) then
               call note_net_force(model, out, net_tol, report%net_noted, unheld)
            else
               call note_net_force(model, out, net_tol, unheld=unheld)
            end if
         end if
         ! SOLVE of a model that would accelerate as one body without end:
         ! no cycle can bring it to rest, so none is run (run_solve says why)
         nrun = ncycles
         if (present(solve) .and. unheld) then
            solve%unheld = .true.
            nrun = 0
         end if
         if (ncycles > 0) call note_stiff_state(model, wk%cw, ncycles, out)
         if (ncycles > 0) then
            if (hist%typed > hist%n) then
               call out%line('CYCLE: note: TYPE '//trim(itoa(hist%typed))//' names no history ('// &
                             trim(itoa(hist%n))//' defined); nothing is typed')
               call out%row('   cycle   max unbalanced force')
            else if (hist%typed > 0) then
               call out%row('   cycle   max unbalanced force   history '//trim(itoa(hist%typed)))
            else
               call out%row('   cycle   max unbalanced force')
            end if
         end if
         call progress%start(out, ncycles, 'cycle')
         step0 = mech%step
         call system_clock(t1)
         setup = real(t1 - t0, wp)/real(max(rate, 1_i8), wp)
         failed = .false.
         turn_taken = 0.0_wp
         drift_taken = 0.0_wp
         do n = 1, nrun
            alpha = wk%alpha_rayleigh
            if (mech%damping == damping_auto) alpha = mech%auto_alpha
            aloc = merge(mech%local_alpha, 0.0_wp, mech%damping == damping_local)
            ! the first step of a CYCLE has no force sums of a step before it
            probing = mech%damping == damping_auto .and. mech%probe_time >= 0.0_wp .and. n > 1
            call motion_save(wk%mw, geo)
            if (wk%mw%sd%active) call sdef_save(wk%mw%sd, geo)
            if (wk%sw%active) call structure_save(model%structures, wk%sw)
            if (wk%sw%rw%active) call reinforce_save(model%reinforcement, wk%sw%rw)
            do i = 1, size(stages)
               call system_clock(ts0)
               call run_stage(stages(i))
               call system_clock(ts1)
               ticks(i) = ticks(i) + (ts1 - ts0)
               if (failed) exit
            end do
            if (failed) exit
            if (mod(n, every) == 0 .or. n == ncycles) then
               if (hist%typed > 0 .and. hist%typed <= hist%n) then
                  call history_values(hist, geo, mech, hv, model%fluid, model%reinforcement, &
                                      model%materials)
                  write (line, '(i8,3x,a,6x,a)') mech%step, fmt_real(mot%unbal, 15, 6), &
                     fmt_real(hv(hist%typed), 15, 6)
               else
                  write (line, '(i8,3x,a)') mech%step, fmt_real(mot%unbal, 15, 6)
               end if
               call out%row(trim(line))
               ! the first step moves the model by the force sums of the last
               ! CYCLE: a load given since (BOUNDARY STRESS) is not in its
               ! unbalanced force yet, and a SOLVE with HIST NCYC 1 ended
               ! there "balanced" without taking the load
               if (present(solve) .and. n > 1) then
                  ! the floor is a pass over every block and gridpoint: once a
                  ! SOLVE, and again for a new step (Issue 23; the masses,
                  ! MSCALE's too, are set before the first step)
                  if (mech%dt /= solve%floor_dt) then
                     solve%floor = force_floor(model)
                     solve%floor_dt = mech%dt
                  end if
                  ratio = cycle_force_ratio(model, solve%floor)
                  converged = ratio >= 0.0_wp .and. ratio < solve%ratio_limit
                  solve%idle = ratio < 0.0_wp .and. .not. mot%unbal > solve%floor
                  if (solve%idle) converged = .true.
               end if
            end if
            if (progress%due(n)) then
               if (.not. present(solve)) ratio = cycle_force_ratio(model)
               if (ratio >= 0.0_wp) then
                  call progress%show(n, 'force ratio '//trim(adjustl(fmt_real(ratio, 10, 3))))
               else
                  call progress%show(n, 'max unbalanced force '// &
                                     trim(adjustl(fmt_real(mot%unbal, 10, 3))))
               end if
            end if
            ! Ctrl-C or SIGTERM: the model is whole at the end of a step
            if (interrupt_pending()) then
               interrupted = .true.
               exit
            end if
            if (converged) exit
         end do
         call progress%finish()
         done = mech%step - step0
         call note_turn_hold()
         if (present(solve)) then
            solve%ratio = cycle_force_ratio(model)
            solve%reached = converged
            solve%interrupted = interrupted
            solve%cycles = done
         end if
         if (interrupted) then
            write (line, '(a,i0,a,i0,a,i0,2a)') 'CYCLE interrupted after ', done, ' of ', &
               ncycles, ' cycles: cycle ', mech%step, ', time ', fmt_real(mech%time, 12, 5)
            call out%line(trim(line))
         end if
         if (wk%zw%active) call zones_block_centroids(geo)
         ! an interrupted CYCLE (or a SOLVE that converged) ends as if it had
         ! been asked for the cycles done
         if (model%ffield%np > 1) call ffield_cycle_end(model%ffield, model%bound, mech%time, &
                                                         done, merge(done, ncycles, interrupted &
                                                                     .or. converged))
         if (model%bound%n > 0) call boundary_cycle_end(model%bound, mech%time, done, &
                                                        merge(done, ncycles, interrupted .or. &
                                                              converged), geo)
         call system_clock(t1)
         wall = real(t1 - t0, wp)/real(max(rate, 1_i8), wp)
         if (present(report)) then
            report%timed = .true.
            report%n = size(stages)
            report%ids = 0
            report%ids(1:size(stages)) = stages
            report%seconds = 0.0_wp
            report%seconds(1:size(stages)) = real(ticks, wp)/real(max(rate, 1_i8), wp)
            report%cycles = mech%step - step0
            report%setup = setup
            report%wall = wall
            report%thermal = .false.
            report%handovers = 0
            report%opening_search = wk%searched
            report%searches = wk%searches
         end if
         write (line, '(a,i0,7a,f0.3,3a)') &
            'cycle ', mech%step, ', time ', fmt_real(mech%time, 12, 5), ', timestep ', &
            fmt_real(mech%dt, 11, 4), ', max unbalanced force ', &
            fmt_real(mech%unbalanced, 11, 4), ', ', wall, ' s, ', &
            fmt_real(real(done, wp)/max(wall, 1.0e-9_wp), 10, 3), ' cycles/s'
         call out%line(trim(line))
      end associate
   contains
      !> One stage of step n (engine_stages); a failure sets `failed` (and
      !> `error`, the step undone).
      subroutine run_stage(stage)
         integer, intent(in) :: stage
         type(stage_args_t) :: sa         ! what the stage routines take
         type(motion_result_t) :: part    ! the gridpoint stage's results
         associate (geo => model%geometry, mech => model%mech, hist => model%hist)
            ! the step as it stands at this stage (a stage may shorten dt)
            sa = stage_args_t(motion_step(model%gravity, mech%dt, alpha, aloc), &
                              mech%time + mech%dt, n, ncycles)
            sa%ms%probe = probing
            select case (stage)
            case (stage_block_motion)
               call rigid_motion(geo, wk%mw, sa%ms, mot)
               if (mot%unbal /= mot%unbal .or. mot%unbal > huge(1.0_wp)) then
                  write (line, '(a,i0)') 'block ', mot%at
                  call non_finite(trim(line), geo%blocks%xc(mot%at), geo%blocks%yc(mot%at))
               end if
            case (stage_block_velocity)
               sa%res = mot
               call rigid_velocity_step(rvw, model%bound, geo, wk%mw, sa)
               mot = sa%res
            case (stage_sdef)
               call sdef_motion(geo, wk%mw%sd, sa)
               if (sa%bad > 0) then
                  write (line, '(a,i0,a)') 'SDEF block ', sa%bad, ' (strain rate)'
                  call non_finite(trim(line), geo%blocks%xc(sa%bad), geo%blocks%yc(sa%bad))
                  return
               end if
               call motion_add(mot, sa%res)
            case (stage_gridpoint_motion)
               call gridpoint_motion(geo, wk%zw, sa%ms, part, wk%mw%g)
               wk%mw%grid_saved = wk%zw%active
               call add_motion(part, 'gridpoint', geo%gridpoints%x, geo%gridpoints%y, &
                               geo%gridpoints%block)
            case (stage_structure_motion)
               call structure_motion(model%structures, wk%sw, sa)
               call add_motion(sa%res, 'structure node', model%structures%nodes%x, &
                               model%structures%nodes%y)
            case (stage_contact_geometry)
               geometric = mod(mech%step + 1_i8, int(max(1_ip, mech%nupcon), i8)) == 0_i8
               bad = 0
               if (wk%mw%may_skip) then
                  ! overlaps beyond overlap_screen x OVTOL flagged (the next
                  ! step copies its corners)
                  call contact_geometry_pass(wk%cw, geo, overlap_screen*ovtol, bad)
                  wk%mw%safe = bad == 0
                  ! every contact's own tolerance is at least OVTOL, and bad has
                  ! the largest overlap of those flagged: none fails unless it
                  ! passes OVTOL
                  if (bad > 0) then
                     if (.not. -wk%cw%gap_new(bad) > ovtol) bad = 0
                  end if
               else if (geometric) then
                  call contact_geometry_pass(wk%cw, geo, ovtol, bad)
               end if
               ! some contact past OVTOL: those few judged against their own
               ! tolerance (contact_overlap_limit: from their rounded corners
               ! unless SET OVTOL gave the limit); the common case of a
               ! stressed model within OVTOL skips this second pass
               if (bad > 0) then
                  call overlap_judge(geo, wk%cw%void, wk%cw%gap_new, ovtol, mech%ovtol > 0.0_wp, &
                                     bad, ov_limit, ov_over)
                  if (bad == 0 .and. ov_over > 0 .and. .not. overlap_noted) &
                     call note_overlap_past(ov_over)
               end if
               if (bad > 0) then
                  write (line, '(a,i0,a,i0,a,i0,9a,i0)') &
                     'Contact Overlap Too Great: contact ', bad, ' between blocks ', &
                     geo%contacts%block1(bad), ' and ', geo%contacts%block2(bad), ' at (', &
                     fmt_real(geo%contacts%x(bad), 12, 5), ', ', &
                     fmt_real(geo%contacts%y(bad), 12, 5), &
                     '), overlap ', fmt_real(-wk%cw%gap_new(bad), 10, 3), ' > ', &
                     fmt_real(ov_limit, 10, 3), '; model kept as after cycle ', mech%step
                  ov_bad = -wk%cw%gap_new(bad)
                  call undo_step()
                  call contact_geometry_pass(wk%cw, geo, huge(1.0_wp), ub)
                  ! the causes of UDEC manual (ICG1.5, 1989), Section 5.3,
                  ! the one this contact shows first
                  call set_error(error, trim(line)//overlap_cause(model, bad, &
                                 ov_bad + wk%cw%gap_new(bad), ov_limit, ovtol, step_load, pull), &
                                 numerical=.true.)
                  failed = .true.
               end if
            case (stage_contact_forces)
               if (wk%zw%active) call zones_clear_forces(geo)
               call contact_force_pass(wk%cw, geo, mech%dt, geometric)
            case (stage_zone_stresses)
               call zones_stress_pass(geo, wk%zw, mech%dt)
               if (wk%zw%stiffer) then
                  ! zones flattened by large strain: stiffness bounds and time
                  ! step from their current shape (the masses stay)
                  call zones_stiffness(geo, model%materials, wk%zw)
                  if (model%be%linked) call be_stiffness_bound(model%be, geo, wk%zw%kgp)
                  mech%dt = cycle_timestep(model, wk, wk%dt_unbound)
                  call fluid_limit_dt(model, wk)
               end if
            case (stage_structures)
               call structure_force_pass(model%structures, geo, wk%sw, sa)
            case (stage_reinforcement)
               call reinforce_step(model%reinforcement, geo, wk%sw%rw, sa)
               call add_motion(sa%res, 'cable node', model%reinforcement%nodes%x, &
                               model%reinforcement%nodes%y)
            case (stage_fluid)
               call fluid_step(model%fluid, geo, wk%fw, model%gravity, mech%dt, mech%frac_fluid, &
                               dpmax)
               if (n == 1 .and. model%fluid%sflow) call note_ptol()
               if (n == 1) call note_no_flow()
               if (wk%fw%too_stiff > 0) then
                  associate (dm => geo%domains)
                     k = dm%ring(dm%first(wk%fw%too_stiff))
                     write (line, '(a,i0,3a)') 'domain ', wk%fw%too_stiff, ' (volume ', &
                        trim(format_real(wk%fw%vnew(wk%fw%too_stiff))), &
                        ') needs more than 1e6 '// &
                        'transient flow sub-steps in one mechanical step (SET SFLOW for steady '// &
                        'flow, or a lower fluid bulk modulus); at'
                  end associate
                  call undo_step()
                  call set_error(error, 'CYCLE: '//trim(line)//' ('// &
                                 trim(format_real(geo%contacts%x(k)))//', '// &
                                 trim(format_real(geo%contacts%y(k)))// &
                                 '); model kept as after cycle '//trim(itoa(int(mech%step))), &
                                 numerical=.true.)
                  failed = .true.
                  return
               end if
               if (wk%fw%nsub > 1000 .and. .not. slow_flow_noted) then
                  ! each cycle pays for every sub-step: say why the CYCLE is slow
                  call progress%finish()
                  write (line, '(a,i0,a)') 'CYCLE: note: transient joint flow needs ', &
                     wk%fw%nsub, &
                     ' flow sub-steps in each mechanical step (the fluid bulk modulus is stiff '// &
                     'for these apertures); SET SFLOW gives steady flow, a lower BULKW a '// &
                     'larger step'
                  call out%line(trim(line))
                  slow_flow_noted = .true.
               end if
               call fluid_forces(model%fluid, geo, wk%fw, model%gravity)
            case (stage_ffield)
               call ffield_column_step(model%ffield, wk%ffw, model%bound, sa)
               if (sa%bad > 0) then
                  write (line, '(a,i0)') 'free-field gridpoint ', sa%bad
                  call non_finite(trim(line), 0.0_wp, &
                                  model%ffield%yl + real(sa%bad - 1, wp)*model%ffield%dy)
                  return
               end if
               call ffield_apply(model%ffield, wk%ffw, model%bound, geo, wk%vw)
            case (stage_boundaries)
               call zones_pressure_step(model%bound, geo, sa)
               if (model%bound%n > 0) &
                  call boundary_step(model%bound, geo, sa, mech%fxhis, mech%fyhis)
               if (wk%vw%n > 0) call viscous_step(wk%vw, model%bound, geo)
            case (stage_be)
               call be_step(model%be, geo)
            case (stage_clock)
               mech%unbalanced = mot%unbal
               mech%time = mech%time + mech%dt
               mech%step = mech%step + 1
               model%cycled = .true.
            case (stage_damping)
               if (mech%probe_time >= 0.0_wp) then
                  call damping_probe(mech, mot, probing)
               else if (mot%dke > 0.0_wp) then
                  if (mot%edamp < mech%auto_fac*mot%dke) then
                     mech%auto_alpha = mech%auto_alpha*mech%auto_mult2
                  else
                     mech%auto_alpha = mech%auto_alpha*mech%auto_mult1
                  end if
                  mech%auto_alpha = min(max(mech%auto_alpha, 1.0e-6_wp/mech%dt), 1.0_wp/mech%dt)
               end if
            case (stage_turn_hold)
               call turn_hold_step(model, wk%mw%m_in, wk%mw%i_in, wk%zw, wk%sw, net_tol, &
                                   mech%dt, turn_w, drift_w)
               turn_taken = turn_taken + turn_w
               drift_taken = drift_taken + drift_w
            case (stage_contact_update)
               mech%motion_since_scan = mech%motion_since_scan + mot%travel
               if (mech%motion_since_scan > 0.25_wp*margin) then
                  call contact_scan(geo, margin, nnew, nbroken, ovscan)
                  call search_done(model, margin)
                  wk%searches = wk%searches + 1
                  call contact_groups_build(wk%cw, geo, model%materials, mech%clemin, &
                                            mech%clemin_auto, error)
                  if (allocated(error)) then
                     failed = .true.
                     return
                  end if
                  call fluid_ready(model, wk%fw)
                  mech%dt = cycle_timestep(model, wk, wk%dt_unbound)
                  call note_state_stiffness(wk%cw, geo)
                  call fluid_limit_dt(model, wk)
                  ! the scan measured the overlaps of the contacts kept and made
                  wk%mw%safe = ovscan <= overlap_screen*ovtol
               else if (wk%cw%kstate > wk%cw%kstate_dt) then
                  ! a contact of a state-dependent law (JCONS 3 with JEN or
                  ! JES) is stiffer than the step allows: the step follows at
                  ! once (contact_state_stiffness). It grows back only at the
                  ! next scan or CYCLE: a joint that softens by opening
                  ! (sigma_n -> 0) can close again within a step
                  mech%dt = min(mech%dt, cycle_timestep(model, wk))
                  wk%cw%kstate_dt = state_headroom*wk%cw%kstate
                  call fluid_limit_dt(model, wk)
               end if
            case (stage_histories)
               if (hist%n > 0 .and. mod(mech%step, int(hist%ncyc, i8)) == 0_i8) then
                  call history_values(hist, geo, mech, hv, model%fluid, model%reinforcement, &
                                      model%materials)
                  call history_record(hist, mech%time, int(mech%step, ip), hv)
               end if
            end select
         end associate
      end subroutine run_stage

      !> Once a session (the report's flag; every CYCLE without a report):
      !> the turn hold took out a turn or a drift worth noting, more than
      !> 1e-6 rad or 1e-6 m summed over this CYCLE (engine_turn).
      subroutine note_turn_hold()
         if (.not. (turn_taken > 1.0e-6_wp .or. drift_taken > 1.0e-6_wp)) return
         if (present(report)) then
            if (report%turn_noted) return
            report%turn_noted = .true.
         end if
         call out%line('CYCLE: note: nothing holds this model but its boundary stresses (no '// &
                       'FIX, no velocity, viscous or free-field boundary, no BE far field), so '// &
                       'nothing resists its moving as one body; under DAMP AUTO or LOCAL '// &
                       'its turn ('// &
                       trim(adjustl(fmt_real(turn_taken, 10, 3)))//' rad in this CYCLE) and '// &
                       'a drift within the loads'' balance ('// &
                       trim(adjustl(fmt_real(drift_taken, 10, 3)))//' m) are held at every '// &
                       'step, as the rock around the model would hold it (docs/mechanics.md '// &
                       '"A model held by stresses alone")')
      end subroutine note_turn_hold

      !> A contact past OVTOL within its own tolerance (contact_overlap_limit):
      !> the elastic closure of a joint under a high stress, which runs on.
      !> Said once a CYCLE, naming the contact, its overlap and stress,
      !> and the remedies that keep overlaps within OVTOL (manual Section 5.3).
      subroutine note_overlap_past(c)
         integer(ip), intent(in) :: c
         character(len=:), allocatable :: load
         real(wp) :: kn
         overlap_noted = .true.
         associate (ct => model%geometry%contacts)
            if (ct%length(c) > 0.0_wp) then
               load = 'normal stress '//trim(format_real(ct%state%fn(c)/ct%length(c)))
            else
               load = 'normal force '//trim(format_real(ct%state%fn(c)))//' (a contact of zero length)'
            end if
            kn = 0.0_wp
            if (ct%jmat(c) > 0) kn = model%materials%get(int(ct%jmat(c)), prop_jkn)
            call progress%finish()
            call out%line('CYCLE: note: contact '//trim(itoa(c))//' between blocks '// &
                          trim(itoa(ct%block1(c)))//' and '//trim(itoa(ct%block2(c)))//' at ('// &
                          trim(format_real(ct%x(c)))//', '//trim(format_real(ct%y(c)))// &
                          ') overlaps by '//trim(format_real(-wk%cw%gap_new(c)))//', past OVTOL '// &
                          trim(format_real(ovtol))//', under a '//load//' (JKN x OVTOL = '// &
                          trim(format_real(kn*ovtol))//'), as joints closing elastically under '// &
                          'a high stress do; it runs '// &
                          'on while within the tolerance of its rounded corners, '// &
                          trim(format_real(contact_overlap_limit(model%geometry, c, ovtol, .false.)))// &
                          ' (half the overlap their normal stays defined for, at most 2 ROUND), '// &
                          'and '// &
                          'stops the run beyond it. To keep overlaps '// &
                          'within OVTOL raise JKN or ROUND (manual Section 5.3); SET OVTOL t '// &
                          'makes t the limit of every contact')
         end associate
      end subroutine note_overlap_past

      !> SET PTOL is an absolute pressure change (fluid_flow): one far below
      !> the model's pressures (the default 0.01 in a deck in Pa) triggers
      !> the mechanics after every steady-flow sweep, and the flow converges
      !> slowly. Said once per value of PTOL.
      subroutine note_ptol()
         real(wp) :: scale
         if (model%fluid%ptol_noted) return
         scale = fluid_pressure_scale(model%fluid, model%geometry)
         if (.not. model%fluid%ptol < 1.0e-4_wp*scale) return
         model%fluid%ptol_noted = .true.
         call progress%finish()
         call out%line('CYCLE: note: SET PTOL '//trim(format_real(model%fluid%ptol))// &
                       ', the pressure change that triggers the mechanics under SET SFLOW '// &
                       '(Section 3.12), is below 1e-4 of the pressures ('// &
                       trim(format_real(scale))//'): every sweep triggers them; try SET PTOL '// &
                       trim(format_real(0.01_wp*scale)))
      end subroutine note_ptol

      !> Pressures given (PFIX, BOUNDARY PP) but no contact conducts: the
      !> joints closed by their normal stress (INSITU, boundary stresses) to
      !> a hydraulic aperture AZERO + un of 0, the ARES default 0 (Section
      !> 4, PROPERTY; Eq. 55), or JPERM 0. The flow stays 0 everywhere,
      !> whatever the order of FLUID and INSITU: said at each such CYCLE.
      subroutine note_no_flow()
         integer(ip) :: nclosed, nlive
         real(wp) :: scale
         scale = fluid_pressure_scale(model%fluid, model%geometry)
         if (.not. scale > 0.0_wp) return
         call fluid_closed_count(model%geometry, wk%fw, nclosed, nlive)
         if (nlive == 0 .or. nclosed < nlive) return
         call progress%finish()
         call out%line('CYCLE: note: no joint conducts water: all '//trim(itoa(nlive))// &
                       ' contacts have a hydraulic aperture AZERO + un of 0 (closed by their '// &
                       'normal stress; Section 3.12, Eq. 55) or a permeability JPERM / CPERM '// &
                       'of 0, so the pressures given (up to '//trim(format_real(scale))// &
                       ') drive no flow; give the joints a residual aperture, PROPERTY JMAT n '// &
                       'ARES a (the default is 0), or a larger AZERO')
      end subroutine note_no_flow

      !> Put the model back as it was before this step (block and gridpoint
      !> motion, structure nodes).
      subroutine undo_step()
         call motion_restore(wk%mw, model%geometry)
         if (wk%mw%sd%active) call sdef_restore(wk%mw%sd, model%geometry)
         if (wk%sw%active) call structure_restore(model%structures, wk%sw)
         if (wk%sw%rw%active) call reinforce_restore(model%reinforcement, wk%sw%rw)
      end subroutine undo_step

      !> The results of a motion stage join the step's (motion_add); a
      !> non-finite unbalanced force at point part%at of the stage's points
      !> (x, y), named `what` and (`owner`) its block, ends the CYCLE
      !> (non_finite) instead.
      subroutine add_motion(part, what, x, y, owner)
         type(motion_result_t), intent(in) :: part
         character(len=*), intent(in) :: what
         real(wp), intent(in) :: x(:), y(:)
         integer(ip), intent(in), optional :: owner(:)
         if (part%unbal /= part%unbal .or. part%unbal > huge(1.0_wp)) then
            if (present(owner)) then
               write (line, '(2a,i0,a,i0)') what, ' ', part%at, ' of block ', owner(part%at)
            else
               write (line, '(2a,i0)') what, ' ', part%at
            end if
            call non_finite(trim(line), x(part%at), y(part%at))
            return
         end if
         call motion_add(mot, part)
      end subroutine add_motion

      !> A non-finite unbalanced force at `what` (x, y): the step is undone
      !> and the CYCLE ends with an error naming the entity and its position.
      subroutine non_finite(what, x, y)
         character(len=*), intent(in) :: what
         real(wp), intent(in) :: x, y
         character(len=240) :: msg
         call undo_step()
         write (msg, '(7a,i0)') 'CYCLE: numerical failure: ', what, ' at (', fmt_real(x, 12, 5), ', ', &
            fmt_real(y, 12, 5), ') has a non-finite unbalanced force; the cycle stopped after step ', &
            model%mech%step
         call set_error(error, trim(msg), numerical=.true.)
         failed = .true.
      end subroutine non_finite
   end subroutine cycle_run


   !> SOLVE's convergence measure: the maximum unbalanced force of the last
   !> step over the mean magnitude |(fn, fs)| of the contacts that carry a
   !> force; with none, over the mean weight m |g| of the free gridpoints;
   !> with no weight either (a lone deformable block under boundary stress,
   !> no gravity), over the mean internal force of the stressed zones,
   !> |sigma| sqrt(A) (the Frobenius norm of the zone's stress times the side
   !> of a square of its area: the size of the force a zone's stress puts on
   !> its gridpoints). Forces at or below the round-off floor (`floor`,
   !> below) do not count. -1 when none of these gives a force: the ratio is
   !> undefined (SOLVE ends when the unbalanced force is below the floor too:
   !> nothing loads the model).
   !> The floor is 4 m_min eps X / dt^2: m_min the lightest free block or
   !> gridpoint, X the largest coordinate of one, eps the machine epsilon.
   !> A force is computed from coordinates (a contact's overlap, a zone's
   !> strain) known to eps X, through a stiffness that the step keeps below
   !> 4 m_min / dt^2 (the critical step 2 sqrt(m / k); rigid blocks at
   !> FRACTION 0.1 stay below 0.04 m_min / dt^2), so a force below the floor
   !> is round-off. An unloaded jointed rigid model (20 m, no gravity,
   !> boundary or stress) kept contacts at 1e-5 N and an unbalanced force of
   !> 4e-5 N for ever (ratio 4 after 100 000 cycles; floor 4.4e-3 N); a real
   !> load is orders above it (the weight of that model's lightest block is
   !> 1.2e5 floors at g = 10 m/s^2).
   !> `floor`: the floor worked out already (force_floor), else it is here.
   real(wp) function cycle_force_ratio(model, floor) result(ratio)
      type(model_t), intent(in) :: model
      real(wp), intent(in), optional :: floor
      real(wp) :: total, g, fmin
      integer(ip) :: c, n, k, z
      ratio = -1.0_wp
      total = 0.0_wp
      n = 0
      if (present(floor)) then
         fmin = floor
      else
         fmin = force_floor(model)
      end if
      associate (con => model%geometry%contacts, gp => model%geometry%gridpoints, &
                 zn => model%geometry%zones)
         do c = 1, con%n
            if (con%live(c)) call add(hypot(con%state%fn(c), con%state%fs(c)))
         end do
         if (n == 0) then
            g = hypot(model%gravity(1), model%gravity(2))
            do k = 1, gp%n
               if (.not. gp%live(k) .or. gp%vfix(k) == ior(vfix_x, vfix_y)) cycle
               call add(gp%mass(k)*g)
            end do
         end if
         if (n == 0) then
            do z = 1, zn%n
               if (zn%live(z)) call add(sqrt((zn%sxx(z)**2 + zn%syy(z)**2 + 2.0_wp*zn%sxy(z)**2) &
                                             *abs(zone_area(model%geometry, z))))
            end do
         end if
      end associate
      if (n == 0 .or. .not. total > 0.0_wp) return
      ratio = model%mech%unbalanced/(total/real(n, wp))
   contains
      !> One force of the mean: only forces above round-off count.
      subroutine add(f)
         real(wp), intent(in) :: f
         if (f > fmin) then
            total = total + f
            n = n + 1
         end if
      end subroutine add
   end function cycle_force_ratio

   !> The round-off floor of the model's forces, 4 m_min eps X / dt^2
   !> (cycle_force_ratio); 0 without a step or a free mass.
   real(wp) function force_floor(model) result(fmin)
      type(model_t), intent(in) :: model
      real(wp) :: mmin, x
      integer(ip) :: b, k
      fmin = 0.0_wp
      mmin = huge(1.0_wp)
      x = 0.0_wp
      associate (bl => model%geometry%blocks, gp => model%geometry%gridpoints)
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fixed(b) .or. bl%nzone(b) > 0) cycle
            if (.not. (bl%mass(b) > 0.0_wp)) cycle
            mmin = min(mmin, bl%mass(b))
            x = max(x, abs(bl%xc(b)), abs(bl%yc(b)))
         end do
         do k = 1, gp%n
            if (.not. gp%live(k) .or. gp%vfix(k) == ior(vfix_x, vfix_y)) cycle
            if (.not. (gp%mass(k) > 0.0_wp)) cycle
            mmin = min(mmin, gp%mass(k))
            x = max(x, abs(gp%x(k)), abs(gp%y(k)))
         end do
      end associate
      if (.not. (mmin < huge(1.0_wp) .and. model%mech%dt > 0.0_wp)) return
      fmin = 4.0_wp*mmin*epsilon(1.0_wp)*x/model%mech%dt**2
      if (.not. fmin < huge(1.0_wp)) fmin = 0.0_wp
   end function force_floor

   !> Force sums of the state as it is, before the first step a model takes
   !> (cycle_run): the force stages of the model's list run once with block
   !> and gridpoint velocities set to zero, so joint and zone stresses get no
   !> increment, and restored afterwards; applied boundary loads and SET
   !> ZPRESS sources at the start time are added as a step would add them.
   subroutine assemble_initial_forces(model, wk, ncycles, stages)
      type(model_t), intent(inout) :: model
      type(cycle_work_t), intent(inout) :: wk
      integer(i8), intent(in) :: ncycles
      integer, intent(in) :: stages(:)
      real(wp), allocatable :: bv(:, :), gv(:, :)
      integer(ip) :: nb, ng
      type(stage_args_t) :: sa
      integer :: i
      associate (geo => model%geometry, mech => model%mech)
         ! a step of length 0 at the start time, before the first step
         sa = stage_args_t(motion_step(model%gravity, 0.0_wp, 0.0_wp, 0.0_wp), mech%time, 0_i8, &
                           ncycles)
         nb = geo%blocks%n
         ng = geo%gridpoints%n
         allocate (bv(3, nb), gv(2, ng))
         bv(1, :) = geo%blocks%vx(1:nb); bv(2, :) = geo%blocks%vy(1:nb)
         bv(3, :) = geo%blocks%vr(1:nb)
         gv(1, :) = geo%gridpoints%vx(1:ng); gv(2, :) = geo%gridpoints%vy(1:ng)
         geo%blocks%vx(1:nb) = 0.0_wp; geo%blocks%vy(1:nb) = 0.0_wp
         geo%blocks%vr(1:nb) = 0.0_wp
         geo%gridpoints%vx(1:ng) = 0.0_wp; geo%gridpoints%vy(1:ng) = 0.0_wp
         do i = 1, size(stages)
            select case (stages(i))
            case (stage_contact_forces)
               if (wk%zw%active) call zones_clear_forces(geo)
               call contact_force_pass(wk%cw, geo, mech%dt, .false.)
            case (stage_zone_stresses)
               call zones_stress_pass(geo, wk%zw, mech%dt)
            case (stage_structures)
               call structure_force_pass(model%structures, geo, wk%sw, sa)
            case (stage_reinforcement)
               call reinforce_step(model%reinforcement, geo, wk%sw%rw, sa)
            case (stage_fluid)
               call fluid_forces(model%fluid, geo, wk%fw, model%gravity)
            case (stage_ffield)
               call ffield_apply(model%ffield, wk%ffw, model%bound, geo, wk%vw)
            end select
         end do
         geo%blocks%vx(1:nb) = bv(1, :); geo%blocks%vy(1:nb) = bv(2, :)
         geo%blocks%vr(1:nb) = bv(3, :)
         geo%gridpoints%vx(1:ng) = gv(1, :); geo%gridpoints%vy(1:ng) = gv(2, :)
         ! boundary velocities and loads after the velocities are back
         if (any(stages == stage_boundaries)) then
            call zones_pressure_step(model%bound, geo, sa)
            if (model%bound%n > 0) call boundary_step(model%bound, geo, sa, mech%fxhis, mech%fyhis)
         end if
      end associate
   end subroutine assemble_initial_forces

end module engine_cycle
