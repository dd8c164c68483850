!> RUN: thermal steps (manual Sections 7.4.1 and 7.5.1). Thermal steps are a
!> loop of their own; with SET NTHER > 0 they hand over to NMECH mechanical
!> cycles every NTHER steps or when the temperature change since the last
!> mechanical cycles exceeds RUN TEMP. The thermal stresses of the
!> accumulated temperature change are put into the zones before every
!> mechanical hand-over and at the end of the RUN.
module engine_thermal
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use core_output, only: output_t, fmt_real, format_real
   use core_progress, only: progress_t
   use model_state, only: model_t
   use model_thermal, only: thermal_t, thermal_add_sample
   use thermal_conduction, only: thermal_work_t, thermal_build, thermal_explicit_step, &
                                 thermal_implicit_step, thermal_store, thermal_apply_stress, &
                                 thermal_auto_dt
   use engine_cycle, only: cycle_run
   use engine_stages, only: cycle_report_t, cycle_report_add
   implicit none
   private
   public :: thermal_run

contains

   !> Thermal steps until STEP, AGE or TEMP stops them (Section 7.4.1). The
   !> mechanical hand-overs' stage times go to `report` (PRINT CYCLE) when
   !> there is at least one.
   subroutine thermal_run(model, implicit, out, error, report)
      type(model_t), intent(inout) :: model
      logical, intent(in) :: implicit
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      type(cycle_report_t), intent(inout), optional :: report
      type(thermal_work_t) :: w
      real(wp) :: dt, dt_auto, temmax
      integer(ip) :: step, since_mech, handovers
      integer :: iterations, total_iterations
      character(len=200) :: line
      character(len=24) :: limit
      character(len=:), allocatable :: reason
      type(progress_t) :: progress
      call thermal_build(model, model%thermal%tol, w, error)
      if (allocated(error)) return
      if (w%ntri == 0) then
         call set_error(error, 'RUN: no block carries a temperature (the model has no '// &
                        'blocks with an area)')
         return
      end if
      dt_auto = thermal_auto_dt(w)
      associate (th => model%thermal)
         if (implicit) then
            dt = th%dt_user
            if (dt <= 0.0_wp) dt = dt_auto
         else
            dt = dt_auto
            if (th%dt_user > 0.0_wp) then
               ! dt_auto = 0: no free node conducts (every gridpoint TFIXed, or
               ! no conductivity), no stability limit applies: DELT is used
               if (dt_auto <= 0.0_wp .or. th%dt_user <= dt_auto) then
                  dt = th%dt_user
               else
                  write (line, '(a,es12.5,a,es12.5)') 'RUN: thermal time step ', th%dt_user, &
                     ' reduced to the explicit limit ', dt_auto
                  call out%line(trim(line))
               end if
            end if
         end if
         if (dt <= 0.0_wp) then
            ! say which: a new user's TFIX over the whole model (the thermal
            ! stress of a uniform heating, manual Section 7.4, TFIX) left
            ! nothing free, or no material has a conductivity
            if (.not. any(.not. w%fixed(1:w%nnode))) then
               call set_error(error, 'RUN: every gridpoint''s temperature is held by TFIX: '// &
                              'nothing to conduct (TFIX itself induced the thermal stresses; '// &
                              'CYCLE takes the mechanical steps, TFREE frees temperatures)')
            else
               call set_error(error, 'RUN: no thermal time step: no block material has a '// &
                              'conductivity or specific heat (PROPERTY COND (XCOND, YCOND) '// &
                              'and SPECHEAT of the MAT of the blocks) and no DELT was given')
            end if
            return
         end if
         th%dt_last = dt
         write (line, '(a,a,a,es12.5,a,i0,a,i0,a)') 'RUN (', merge('implicit', 'explicit', &
            implicit), '): thermal time step ', dt, ', ', w%nnode, ' nodes, ', w%ntri, &
            ' triangles'
         call out%line(trim(line))
         reason = 'STEP limit'
         since_mech = 0
         handovers = 0
         total_iterations = 0
         temmax = maxval(abs(w%acc(1:w%nnode)))
         ! on a terminal: one progress line over the STEP limit (core_progress)
         call progress%start(out, int(th%step_limit, i8), 'thermal step')
         do step = 1, th%step_limit
            if (th%age_test .and. th%time >= th%age*(1.0_wp - 1.0e-12_wp)) then
               reason = 'AGE limit'
               exit
            end if
            if (implicit) then
               call thermal_implicit_step(w, th, dt, temmax, iterations, error)
               if (allocated(error)) then
                  call thermal_store(model, w)
                  return
               end if
               total_iterations = total_iterations + iterations
            else
               call thermal_explicit_step(w, th, dt, temmax)
            end if
            th%time = th%time + dt
            th%nsteps = th%nsteps + 1
            since_mech = since_mech + 1
            if (th%nthis > 0) then
               if (mod(th%nsteps, th%ntcyc) == 0) call sample(th)
            end if
            if (temmax /= temmax) then
               call thermal_store(model, w)
               call set_error(error, 'RUN: the temperatures became NaN; reduce the thermal '// &
                              'time step')
               return
            end if
            if (temmax > th%temp_limit .or. (th%nther > 0 .and. since_mech >= th%nther)) then
               if (th%nther == 0) then
                  reason = 'TEMP limit (temperature change since the last mechanical cycles)'
                  exit
               end if
               call progress%finish()
               call mechanical_handover(model, w, out, error, handovers == 0, report)
               if (allocated(error)) return
               since_mech = 0
               handovers = handovers + 1
            end if
            if (progress%due(int(step, i8))) &
               call progress%show(int(step, i8), 'max temperature change '// &
                                  trim(adjustl(fmt_real(temmax, 10, 3))))
            if (interrupt_pending()) then
               reason = 'interrupt (Ctrl-C or SIGTERM)'
               exit
            end if
         end do
         call progress%finish()
         call thermal_store(model, w)
         write (line, '(a,a,a,i0,a,es12.5,a,es12.5)') 'RUN stopped by the ', reason, &
            ': thermal step ', th%nsteps, ', thermal time ', th%time, ', max change ', temmax
         call out%line(trim(line))
         ! a new user's `RUN AGE 2E7` stopped at step 1 by the TEMP limit (default
         ! 20, manual Section 7.4, RUN: "the values of the others should be set
         ! very high"): say which limit to raise to reach the AGE asked for
         if (th%age_test .and. th%time < th%age*(1.0_wp - 1.0e-12_wp) .and. &
             (reason(1:4) == 'TEMP' .or. reason(1:4) == 'STEP')) then
            if (reason(1:4) == 'TEMP') then
               limit = format_real(th%temp_limit)
            else
               write (limit, '(i0)') th%step_limit
            end if
            call out%line('note: RUN: the AGE '//trim(format_real(th%age))// &
                          ' is not reached: the '//reason(1:4)//' limit ('//trim(limit)// &
                          ') stopped it first; give it higher (RUN AGE .. TEMP .. STEP ..; '// &
                          'manual Section 7.4, RUN: set the limits other than the one meant '// &
                          'very high)')
         end if
         if (implicit) then
            write (line, '(a,i0)') 'RUN: Jacobi iterations in total: ', total_iterations
            call out%line(trim(line))
         end if
      end associate
      call thermal_apply_stress(model)

   contains

      !> THIST sample from the node temperatures; THIST TYPE shows one.
      subroutine sample(th)
         type(thermal_t), intent(inout) :: th
         real(wp) :: values(th%nthis)
         integer(ip) :: h, g
         do h = 1, th%nthis
            g = th%this_gp(h)
            if (allocated(th%this_kind)) then
               if (th%this_kind(h) == 1) g = w%ng + g
               if (th%this_kind(h) == 2) g = w%ng + w%nc + g
            end if
            values(h) = 0.0_wp
            if (g < 1 .or. g > size(w%node_of_gp)) cycle
            if (w%node_of_gp(g) > 0) values(h) = w%t(w%node_of_gp(g))
         end do
         call thermal_add_sample(th, values)
         if (th%this_type > 0 .and. th%this_type <= th%nthis) then
            write (line, '(a,i0,a,es12.5,a,i0,a,es14.6)') 'thermal step ', th%nsteps, &
               ', time ', th%time, ', temperature ', th%this_type, ': ', values(th%this_type)
            call out%row(trim(line))
         end if
      end subroutine sample
   end subroutine thermal_run

   !> NMECH mechanical cycles with the thermal stresses applied (SET NTHER),
   !> timed into `report` (`first`: the RUN's first hand-over).
   subroutine mechanical_handover(model, w, out, error, first, report)
      type(model_t), intent(inout) :: model
      type(thermal_work_t), intent(inout) :: w
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: first
      type(cycle_report_t), intent(inout), optional :: report
      type(cycle_report_t) :: part
      call thermal_store(model, w)
      call thermal_apply_stress(model)
      w%acc(1:w%nnode) = 0.0_wp
      if (present(report)) then
         part%net_noted = report%net_noted
         part%mscale_noted = report%mscale_noted
         part%turn_noted = report%turn_noted
      end if
      ! the thermal steps since the last hand-over may have changed what the
      ! contacts' search found (engine_cycle, search_skippable): search again
      model%mech%search_current = .false.
      model%mech%search_sizes = -1
      call cycle_run(model, int(model%thermal%nmech, i8), out, error, part)
      if (present(report)) call cycle_report_add(report, part, first)
   end subroutine mechanical_handover

end module engine_thermal
