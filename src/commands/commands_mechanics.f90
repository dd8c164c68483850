!> Commands of the rigid-block mechanics (manual Section 4.5): CYCLE, SOLVE
!> (an extension: cycle until the force ratio is small), FIX,
!> FREE, LOAD, FRACTION, DAMPING, MSCALE, HISTORY, RESET, CHANGE and the
!> mechanical SET keywords (CSCAN, DSCAN, UPCON, OVTOL, CLEMIN). Every
!> handler validates the whole line before it changes anything.
module commands_mechanics
   use commands_address, only: resolve_entity, resolve_field
   use model_address, only: ak_block, ak_contact, address_describe
   use core_kinds, only: wp, ip, i8, i1
   use core_error, only: error_t, set_error
   use core_limits, only: check_request
   use core_output, only: output_t, fmt_real, itoa
   use core_files, only: file_rename, temporary_name, check_output_file, file_delete
   use model_state, only: model_t
   use model_properties, only: prop_bulk, prop_shear, prop_jkn, prop_jks
   use model_geometry, only: geometry_t, block_sdef_fields, unzoned_block, geometry_live_blocks
   use model_mechanics, only: damping_none, damping_auto, damping_rayleigh, damping_local, &
                              damping_load_changed
   use model_history, only: history_add, history_clear, history_first, hist_keyword, hist_xvel, &
                            hist_yvel, hist_xdis, hist_ydis, hist_bfx, hist_bfy, hist_bfm, &
                            hist_ndis, hist_sdis, hist_nstr, hist_sstr, hist_unbal, hist_damp, hist_address, &
                            hist_caxial, hist_raxial, hist_rshear, hist_srat, &
                            hist_xhis, hist_yhis, hist_none, hist_sxx, hist_sxy, hist_syy, &
                            hist_gxvel, hist_gydis
   use contact_refresh, only: geometry_refresh
   use contact_domains, only: domains_released
   use contact_joint_law, only: known_jcons
   use engine_cycle, only: cycle_run, solve_t, search_base
   use engine_history, only: history_locate
   use engine_sdef, only: sdef_present
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, cannot_fail, warn_fdef_free
   use commands_geometry, only: remove_partial_cracks_once
   implicit none
   private
   public :: register_mechanics_commands
   public :: set_mechanics_keyword, history_write

   real(wp), parameter :: deg = 57.295779513082320876_wp
   !> SOLVE's cycle limit when CYCLES is not given
   integer(i8), parameter :: solve_default_cycles = 100000_i8

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_mechanics_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('mechanics', 'Cycle', 'c', '', '', '4.5', &
                   'execute n mechanical steps (C is CYCLE, as in the Section 7.8 decks)', &
                   run_cycle, args='n')
      call reg%add('mechanics', 'SOlve', '', '', 'Ratio p;Cycles q', 'udec', &
                   'extension: CYCLE until max unbalanced force / mean contact force < RATIO, ' // &
                   'or CYCLES; says which ended it', run_solve)
      call reg%note('RATIO', default='1e-5')
      call reg%note('CYCLES', default='100000')
      call reg%add('mechanics', 'Fix', 'R', '', '', '4.5', &
                   'fix the velocities of the blocks in a range', handler=do_fix)
      call reg%add('mechanics', 'FREe', 'R', '', '', '4.5', &
                   'free the blocks FIX held', handler=do_fix)
      call reg%add('mechanics', 'LOad', 'Rrr', '', '', '4.5', &
                   'apply a force to the blocks in a range (LO: L is LINK or LOAD)', &
                   handler=do_fix, unit='N', args='xl xu yl yu xload yload')
      call reg%add('mechanics', 'FRAction', 'p[p[p]]', '', '', '4.5', &
                   'fractions of the critical time step: blocks, zones, fluid', run_fraction, &
                   default='0.1 1 1', args='fb [fz [fw]]')
      call reg%add('mechanics', 'Damping', '[n[n]]', '', &
                   'Auto [n[p[p]]];Local [p];Stiffness;Mass;Internal', '4.5', &
                   'damping: AUTO (adaptive), Rayleigh fraction of critical at a frequency, '// &
                   'or LOCAL alpha (extension: -alpha |F| sign(v) per degree of freedom)', &
                   handler=run_damping, unit='- Hz')
      call reg%note('AUTO', default='0.5 0.99 1.05')
      call reg%note('LOCAL', default='0.8')
      call reg%add('mechanics', 'Mscale', '', '', 'ON [n[n]];OFF;PART p', '4.5', &
                   'mass scaling for static solutions', handler=do_mscale)
      call reg%note('PART', unit='s')
      call reg%add('mechanics', 'HIstory', '', '', 'Address ii;BFM q;BFX q;BFY q;CAXial q;Damp;' // &
                   'Function q;List;Ncyc q;NDisplacement q;NStr q;SDisplacement q;SStr q;' // &
                   'RAXial q;RSHear q;SXX rr;SXY rr;SYX rr;SYY rr;SRAT q;Type q;Unbal;' // &
                   'Write qs;XDisplacement rr;' // &
                   'XHIS;XVel rr;YDisplacement rr;YHIS;YVel rr', '4.5', &
                   'record quantities every NCYC steps; list, type or write them', &
                   handler=do_history)
      call reg%note('NCYC', default='10')
      call reg%add('mechanics', 'RESET', '', '', 'Disp;Hist;INterface qq;JDisp;Mat q;Time;' // &
                   'Rota;Stress;THist', '4.5', 'set displacements, histories, time .. to zero', &
                   handler=do_reset)
      call reg%add('mechanics', 'CHange', '[R]', '', 'ANGle rr;INterface qq;Cons c;Mat q;' // &
                   'SDEF;FDEF;JCons c;JMat q', '4.5', &
                   'change materials, models or joint laws of blocks and contacts in a range', &
                   handler=do_change)
      call reg%note('ANGLE', unit='degrees')
      call reg%add_set('mechanics', 'CSCAn q;DScan q;UPcon q;OVtol p;CLEmin p', &
                       act=set_mechanics_keyword)
      call reg%note('UPCON', default='1')
      call reg%note('DSCAN', default='3')
      call reg%note('CSCAN', default='100')
      call reg%note('OVTOL', unit='m', default='half the rounding length')
      call reg%note('CLEMIN', unit='m', default='1/10 of the mean contact length')
   end subroutine register_mechanics_commands

   !> FIX / FREE range: blocks with centroids in the range (velocities held
   !> at their current values / released). LOAD range xload yload: static
   !> centroid loads on them. "FDEF blocks cannot be fixed" (UDEC manual
   !> (ICG1.5, 1989), Section 4.5, FIX): FIX leaves zoned blocks free and
   !> says so; with only zoned blocks in its range it is refused (it would
   !> hold nothing, and a model under gravity would fall).
   subroutine do_fix(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b, n, nz, pass
      character(len=300) :: text
      logical :: fix
      associate (model => ctx%model, out => ctx%out)
         fix = parsed%name == 'FIX'
         associate (bl => model%geometry%blocks)
            do pass = 1, 2          ! 1: count, 2: apply
               n = 0
               nz = 0
               do b = 1, bl%n
                  if (.not. bl%live(b)) cycle
                  if (.not. parsed%range%contains_point(bl%xc(b), bl%yc(b))) cycle
                  if (fix .and. bl%fdef(b)) then
                     nz = nz + 1
                     cycle
                  end if
                  if (pass == 2) then
                     if (parsed%name == 'LOAD') then
                        bl%lx(b) = parsed%real_at(1, 1)
                        bl%ly(b) = parsed%real_at(1, 2)
                     else
                        bl%fixed(b) = fix
                     end if
                  end if
                  n = n + 1
               end do
               if (pass == 1 .and. n == 0 .and. nz > 0) then
                  write (text, '(a,i0,a)') 'FIX: the range holds only zoned (FDEF) blocks (', nz, &
                     '), and FDEF blocks cannot be fixed (manual Section 4.5, FIX): hold their ' &
                     //'gridpoints with BOUNDARY XVEL 0 YVEL 0 on the boundary of the range'
                  call set_error(error, trim(text))
                  return
               end if
            end do
         end associate
         if (parsed%name == 'LOAD') then
            if (n > 0) call damping_load_changed(model%mech, model%geometry%zones%n > 0)
            write (text, '(a,i0,a)') 'LOAD applied to ', n, ' block(s)'
         else
            write (text, '(a,1x,i0,a)') parsed%name, n, ' block(s)'
         end if
         if (n == 0) text = parsed%name//': no block centroid lies in the range'
         call out%line(trim(text))
         if (nz > 0) call warn_fdef_free(out, 'FIX', nz, &
                                         ' zoned (FDEF) block(s) in the range left free')
      end associate
   end subroutine do_fix

   subroutine run_fraction(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: n
      n = parsed%items(1)%count
      if (parsed%real_at(1, 1) > 1.0_wp) then
         call set_error(error, 'FRACTION: fb must be a fraction of the critical time step (0 < fb <= 1)')
         return
      end if
      ctx%model%mech%frac_block = parsed%real_at(1, 1)
      if (n >= 2) ctx%model%mech%frac_zone = parsed%real_at(1, 2)
      if (n >= 3) ctx%model%mech%frac_fluid = parsed%real_at(1, 3)
   end subroutine run_fraction

   !> DAMP as do_damping reads it; a DAMP that sets the model's damping (not
   !> INTERNAL alone) marks it given, so SOLVE leaves it as the user chose.
   subroutine run_damping(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call do_damping(ctx, parsed, error)
      if (.not. allocated(error) .and. parsed%find('INTERNAL') == 0) &
         ctx%model%mech%damping_given = .true.
   end subroutine run_damping

   !> DAMP AUTO <fac mult1 mult2> | DAMP fcrit freq <STIFF> <MASS> <INTERNAL> |
   !> DAMP LOCAL <alpha> (an extension, not in the 1989 manual: the local,
   !> non-viscous damping of later Itasca codes, docs/mechanics.md "Time step
   !> and damping"; Rayleigh INTERNAL on SDEF strain modes stays as given).
   subroutine do_damping(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, n
      real(wp) :: fac, m1, m2
      associate (model => ctx%model, out => ctx%out)
         k = parsed%find('LOCAL')
         if (k > 0) then
            if (parsed%items(1)%count > 0 .or. parsed%find('AUTO') > 0 .or. &
                parsed%find('STIFFNESS') > 0 .or. parsed%find('MASS') > 0 .or. &
                parsed%find('INTERNAL') > 0) then
               call set_error(error, 'DAMPING LOCAL: give LOCAL <alpha> alone (not with AUTO, '// &
                              'fcrit freq, STIFFNESS, MASS or INTERNAL)')
               return
            end if
            fac = 0.8_wp
            if (parsed%items(k)%count >= 1) fac = parsed%real_at(k, 1)
            if (.not. (fac > 0.0_wp .and. fac < 1.0_wp)) then
               call set_error(error, 'DAMPING LOCAL: expected alpha between 0 and 1 (the '// &
                              'fraction of each unbalanced force taken against the velocity; '// &
                              'default 0.8), got '//trim(rtoa(fac)))
               return
            end if
            model%mech%damping = damping_local
            model%mech%local_alpha = fac
            return
         end if
         k = parsed%find('AUTO')
         if (k > 0) then
            if (parsed%items(1)%count > 0) then
               call set_error(error, 'DAMPING: give either AUTO <fac mult1 mult2> or fcrit freq, not both')
               return
            end if
            ! DAMP AUTO 0.5 MASS: the Rayleigh keywords were dropped silently
            if (parsed%find('STIFFNESS') > 0 .or. parsed%find('MASS') > 0 .or. &
                parsed%find('INTERNAL') > 0) then
               call set_error(error, 'DAMPING AUTO: STIFFNESS, MASS and INTERNAL belong to the '// &
                              'Rayleigh form DAMP fcrit freq <STIFF> <MASS> <INTERNAL>, not to AUTO')
               return
            end if
            n = parsed%items(k)%count
            fac = 0.5_wp; m1 = 0.99_wp; m2 = 1.05_wp
            if (n >= 1) fac = parsed%real_at(k, 1)
            if (n >= 2) m1 = parsed%real_at(k, 2)
            if (n >= 3) m2 = parsed%real_at(k, 3)
            if (m1 >= 1.0_wp .or. m2 <= 1.0_wp) then
               call set_error(error, 'DAMPING AUTO: expected mult1 < 1 and mult2 > 1 (defaults 0.99 1.05)')
               return
            end if
            model%mech%damping = damping_auto
            model%mech%auto_fac = fac
            model%mech%auto_mult1 = m1
            model%mech%auto_mult2 = m2
            return
         end if
         if (parsed%items(1)%count == 1 .and. parsed%real_at(1, 1) == 0.0_wp .and. &
             parsed%find('STIFFNESS') == 0 .and. parsed%find('MASS') == 0 .and. &
             parsed%find('INTERNAL') == 0) then
            ! DAMP 0: fraction of critical 0, no damping, whatever the frequency
            ! (the manual's form is DAMP fcrit freq; a user switching damping
            ! off for a dynamic stage types the one zero)
            model%mech%rayleigh_fcrit = 0.0_wp
            model%mech%rayleigh_freq = 0.0_wp
            model%mech%rayleigh_stiff = .true.
            model%mech%rayleigh_mass = .true.
            model%mech%damping = damping_none
            return
         end if
         if (parsed%items(1)%count < 2) then
            call set_error(error, 'DAMPING: expected AUTO or two numbers fcrit freq')
            return
         end if
         if (parsed%real_at(1, 1) > 0.0_wp .and. parsed%real_at(1, 2) <= 0.0_wp) then
            ! fcrit 0 switches damping off; a positive fcrit at frequency 0 is a slip
            call set_error(error, 'DAMPING: the centre frequency freq must be > 0 (cycles/sec) ' &
                           //'when fcrit > 0, got '//trim(rtoa(parsed%real_at(1, 2))))
            return
         end if
         if (parsed%find('INTERNAL') > 0) then
            ! the three strain modes of SDEF blocks only; rigid motion keeps its damping
            call read_rayleigh(model%mech%internal_fcrit, model%mech%internal_freq, &
                               model%mech%internal_stiff, model%mech%internal_mass)
            if (.not. sdef_present(model%geometry)) call out%line('note: DAMPING INTERNAL acts on SDEF blocks; '// &
                                                     'the model has none yet (CHANGE SDEF)')
            return
         end if
         call read_rayleigh(model%mech%rayleigh_fcrit, model%mech%rayleigh_freq, &
                            model%mech%rayleigh_stiff, model%mech%rayleigh_mass)
         if (model%mech%rayleigh_fcrit == 0.0_wp .or. model%mech%rayleigh_freq == 0.0_wp) then
            model%mech%damping = damping_none
         else
            model%mech%damping = damping_rayleigh
         end if
      end associate
   contains
      !> fcrit freq <STIFFNESS> <MASS> of the line (both terms when neither is named).
      subroutine read_rayleigh(fcrit, freq, stiff, mass)
         real(wp), intent(out) :: fcrit, freq
         logical, intent(out) :: stiff, mass
         fcrit = parsed%real_at(1, 1)
         freq = parsed%real_at(1, 2)
         stiff = parsed%find('STIFFNESS') > 0 .or. parsed%find('MASS') == 0
         mass = parsed%find('MASS') > 0 .or. parsed%find('STIFFNESS') == 0
      end subroutine read_rayleigh
   end subroutine do_damping

   !> MSCALE ON <zcmass bcmass> | OFF | PART tdel. Without bcmass, rigid
   !> blocks all get the average block mass (the manual's automatic scaling);
   !> without zcmass, zones all get the average zone mass. PART tdel scales
   !> only gridpoints whose own time step is below tdel (rigid blocks keep
   !> their masses).
   subroutine do_mscale(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      associate (model => ctx%model, out => ctx%out)
         k = parsed%find('ON')
         if (k > 0) then
            model%mech%mscale_zone = 0.0_wp
            model%mech%mscale_block = 0.0_wp
            if (parsed%items(k)%count >= 1) model%mech%mscale_zone = parsed%real_at(k, 1)
            if (parsed%items(k)%count >= 2) model%mech%mscale_block = parsed%real_at(k, 2)
            model%mech%mscale = .true.
            model%mech%mscale_part = .false.
         else if (parsed%find('OFF') > 0) then
            model%mech%mscale = .false.
            model%mech%mscale_part = .false.
         else if (parsed%find('PART') > 0) then
            ! partial density scaling of zones (gridpoints) only
            model%mech%mscale = .true.
            model%mech%mscale_part = .true.
            model%mech%mscale_tdel = parsed%real_at(parsed%find('PART'), 1)
            call out%line('MSCALE PART: gridpoint masses raised where needed for time step '// &
                          trim(rtoa(model%mech%mscale_tdel)))
         else
            call set_error(error, 'MSCALE: expected ON, OFF or PART')
         end if
      end associate
   end subroutine do_mscale

   !> HISTORY keyword ...: variables are numbered in the order given.
   subroutine do_history(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, kind, ntyped, kind_used
      integer(ip) :: id, c, nmax
      real(wp) :: x, y, px, py
      character(len=300) :: text
      integer(ip), allocatable :: ids(:), aoff(:)
      integer, allocatable :: akind(:)
      character(len=:), allocatable :: aname
      ! validate the whole line first
      associate (model => ctx%model, out => ctx%out)
         allocate (ids(parsed%nitems), aoff(parsed%nitems), akind(parsed%nitems))
         ids = 0
         aoff = 0
         akind = 0
         ntyped = 0
         do k = 1, parsed%nitems
            select case (parsed%items(k)%name)
            case ('', 'LIST', 'NCYC', 'UNBAL', 'DAMP', 'XVEL', 'YVEL', 'XDISPLACEMENT', &
                  'YDISPLACEMENT', 'SXX', 'SXY', 'SYY', 'SYX')
            case ('TYPE')
               ntyped = parsed%int_at(k, 1)
            case ('FUNCTION')
               ! the 1989 code called a user-written FPLHIS(n) ("available to
               ! users with source codes only", Section 4.5); udec has no such
               ! hook: a new recorded quantity is a history kind in the source
               ! (docs/mechanics.md "Adding a history quantity")
               write (text, '(a,i0,a)') 'HISTORY FUNCTION ', parsed%int_at(k, 1), ': the 1989 '// &
                  'user-written FPLHIS(n) has no counterpart in udec; use a HISTORY keyword, '// &
                  'ADDRESS i j, or a new history kind (docs/mechanics.md "Adding a history ' // &
                  'quantity")'
               call set_error(error, trim(text))
               return
            case ('WRITE')
               if (parsed%int_at(k, 1) > model%hist%n) then
                  write (text, '(a,i0,a,i0,a)') 'HISTORY WRITE: history ', parsed%int_at(k, 1), &
                     ' does not exist (', model%hist%n, ' defined)'
                  call set_error(error, trim(text))
                  return
               end if
            case ('BFX', 'BFY', 'BFM')
               ! n: the block's 1989 address (manual Section 4.5 HISTORY)
               call resolve_entity(model, ak_block, int(parsed%int_at(k, 1), ip), &
                                   'HISTORY '//parsed%items(k)%name, out, ids(k), error, &
                                   nearest=.true.)
               if (allocated(error)) return
            case ('NDISPLACEMENT', 'SDISPLACEMENT', 'NSTR', 'SSTR', 'SRAT')
               ! n: the contact's 1989 address (SDIS(159) in Appendix B, Problem E;
               ! SRAT(3445) in Problem D)
               call geometry_refresh(model%geometry)
               call resolve_entity(model, ak_contact, int(parsed%int_at(k, 1), ip), &
                                   'HISTORY '//parsed%items(k)%name, out, ids(k), error, &
                                   nearest=.true.)
               if (allocated(error)) return
            case ('CAXIAL', 'RAXIAL', 'RSHEAR')
               ! reinforcement forces by element number (PRINT CABLE / PRINT REINFORCE)
               ids(k) = int(parsed%int_at(k, 1), ip)
               nmax = 0
               if (allocated(model%reinforcement)) then
                  nmax = model%reinforcement%reinf%n
                  if (parsed%items(k)%name == 'CAXIAL') nmax = model%reinforcement%elements%n
               end if
               if (ids(k) < 1 .or. ids(k) > nmax) then
                  write (text, '(a,i0,a,i0,a)') 'HISTORY '//parsed%items(k)%name//': element ', &
                     ids(k), ' does not exist (', nmax, trim(merge(' cable elements        ', &
                                                              ' reinforcement elements', &
                                                              parsed%items(k)%name == 'CAXIAL'))//')'
                  call set_error(error, trim(text))
                  return
               end if
            case ('ADDRESS')
               ! ADDRESS i j: any variable by 1989 address and offset (Section 6.1)
               call geometry_refresh(model%geometry)
               call resolve_field(model, 'HISTORY ADDRESS', int(parsed%int_at(k, 1), ip), &
                                  int(parsed%int_at(k, 2), ip), akind(k), ids(k), aoff(k), aname, &
                                  error, out)
               if (allocated(error)) return
            case default
               ! later physics (zone stresses, addresses, boundary histories):
               ! a placeholder keeps the numbering of the variables after it
            end select
         end do
         do k = 1, parsed%nitems
            kind = 0
            id = 0
            x = 0.0_wp
            y = 0.0_wp
            select case (parsed%items(k)%name)
            case ('NCYC')
               model%hist%ncyc = parsed%int_at(k, 1)
            case ('TYPE')
               model%hist%typed = parsed%int_at(k, 1)
            case ('LIST')
               call history_list(model, out)
            case ('WRITE')
               call history_write(model, parsed%int_at(k, 1), parsed%text_at(k, 2), error)
               if (allocated(error)) return
               call out%line('history '//trim(itoa(parsed%int_at(k, 1)))//' written to '// &
                             parsed%text_at(k, 2))
            case ('XVEL'); kind = hist_xvel
            case ('YVEL'); kind = hist_yvel
            case ('XDISPLACEMENT'); kind = hist_xdis
            case ('YDISPLACEMENT'); kind = hist_ydis
            case ('BFX'); kind = hist_bfx
            case ('BFY'); kind = hist_bfy
            case ('BFM'); kind = hist_bfm
            case ('NDISPLACEMENT'); kind = hist_ndis
            case ('SDISPLACEMENT'); kind = hist_sdis
            case ('NSTR'); kind = hist_nstr
            case ('SSTR'); kind = hist_sstr
            case ('SRAT'); kind = hist_srat
            case ('UNBAL'); kind = hist_unbal
            case ('DAMP'); kind = hist_damp
            case ('XHIS'); kind = hist_xhis
            case ('ADDRESS'); kind = hist_address
            case ('CAXIAL'); kind = hist_caxial
            case ('RAXIAL'); kind = hist_raxial
            case ('RSHEAR'); kind = hist_rshear
            case ('YHIS'); kind = hist_yhis
            case ('SXX'); kind = hist_sxx
            case ('SXY'); kind = hist_sxy
            ! the manual's table lists SYX twice, the second time for the yy-stress
            case ('SYY', 'SYX'); kind = hist_syy
            case ('')
            case default
               call history_add(model%hist, hist_none, 0_ip, x, y, x, y)
               call out%line('*** HISTORY '//parsed%items(k)%name//': not yet implemented; history '// &
                             trim(itoa(model%hist%n))//' reads 0')
            end select
            if (kind == 0) cycle
            select case (kind)
            case (hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_sxx, hist_sxy, hist_syy)
               x = parsed%real_at(k, 1)
               y = parsed%real_at(k, 2)
               call history_locate(model%geometry, kind, x, y, kind_used, c, px, py)
               call history_add(model%hist, kind_used, c, x, y, px, py)
               if (c > 0) then
                  write (text, '(a,i0,a,a,a,g0.6,a,g0.6,a,a,1x,i0,a,g0.6,a,g0.6,a)') 'history ', &
                     model%hist%n, ': ', trim(hist_keyword(kind)), ' (', x, ',', y, ') taken at ', &
                     trim(entity_name(kind_used)), c, ' (', px, ',', py, ')'
               else if (kind >= hist_sxx .and. kind <= hist_syy) then
                  write (text, '(a,i0,a,a,a)') 'history ', model%hist%n, ': ', &
                     trim(hist_keyword(kind)), &
                        ' (no zone yet: taken in the nearest zone when cycling)'
               else
                  write (text, '(a,i0,a,a,a)') 'history ', model%hist%n, ': ', &
                     trim(hist_keyword(kind)), ' (no block corner yet: taken at the nearest ' // &
                     'corner when cycling)'
               end if
            case (hist_caxial, hist_raxial, hist_rshear)
               call history_add(model%hist, kind, ids(k), x, y, x, y)
               write (text, '(a,i0,a,a,1x,i0)') 'history ', model%hist%n, ': ', &
                  trim(parsed%items(k)%name), ids(k)
            case (hist_unbal, hist_damp, hist_xhis, hist_yhis)
               call history_add(model%hist, kind, 0_ip, x, y, x, y)
               write (text, '(a,i0,a,a)') 'history ', model%hist%n, ': ', trim(hist_keyword(kind))
            case (hist_address)
               call history_add(model%hist, kind, ids(k), real(akind(k), wp), real(aoff(k), wp), &
                                real(akind(k), wp), real(aoff(k), wp))
               write (text, '(a,i0,a,i0,1x,i0,a,i0,a)') 'history ', model%hist%n, ': ADDRESS ', &
                  parsed%int_at(k, 1), parsed%int_at(k, 2), ' = offset ', aoff(k), ' of the '
               text = trim(text)//' '//address_describe(model, akind(k), ids(k))
            case default
               id = ids(k)
               call history_add(model%hist, kind, id, x, y, x, y)
               write (text, '(a,i0,a,a,1x,i0)') 'history ', model%hist%n, ': ', trim(hist_keyword(kind)), &
                  parsed%int_at(k, 1)
               if ((kind >= hist_ndis .and. kind <= hist_sstr) .or. kind == hist_srat) then
                  text = trim(text)//': '//address_describe(model, ak_contact, id)
               else
                  text = trim(text)//': '//address_describe(model, ak_block, id)
               end if
            end select
            call out%line(trim(text))
         end do
         ! TYPE n is a setting for the cycling to come (manual 4.5): a history
         ! defined later (the Appendix E deck gives TYPE=5 before its 5th
         ! variable) is typed as soon as it exists
         if (ntyped > model%hist%n) &
            call out%line('note: TYPE '//trim(itoa(ntyped))//': history '//trim(itoa(ntyped))// &
                          ' is not defined yet; it is typed while cycling once it is')
      end associate
   contains
      !> What the entity of a located variable is.
      function entity_name(kind_used) result(name)
         integer, intent(in) :: kind_used
         character(len=9) :: name
         if (kind_used >= hist_gxvel .and. kind_used <= hist_gydis) then
            name = 'gridpoint'
         else if (kind_used >= hist_sxx .and. kind_used <= hist_syy) then
            name = 'zone'
         else
            name = 'corner'
         end if
      end function entity_name
      subroutine bad_id(what)
         character(len=*), intent(in) :: what
         write (text, '(a,a,1x,a,1x,i0,a)') 'HISTORY ', parsed%items(k)%name, what, id, &
            ' does not exist (see PRINT '//merge('BLOCK  ', 'CONTACT', what == 'block')//')'
         call set_error(error, trim(text))
      end subroutine bad_id
   end subroutine do_history

   subroutine history_list(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer :: i
      character(len=160) :: text
      if (model%hist%n == 0) then
         call out%line('no histories')
         return
      end if
      write (text, '(a,i0,a,i0)') 'histories sampled every ', model%hist%ncyc, &
         ' cycles; samples taken: ', model%hist%nsample
      call out%line(trim(text))
      do i = 1, model%hist%n
         write (text, '(i4,2x,a5,2x,a,i0,a,a,a,a)') i, hist_keyword(model%hist%kind(i)), &
            'entity ', model%hist%entity(i), '  at ', fmt_real(model%hist%px(i), 12, 5), ' ', &
            fmt_real(model%hist%py(i), 12, 5)
         call out%line(trim(text))
      end do
   end subroutine history_list

   !> HISTORY WRITE n file: '#' header lines, then one 'time value' row per
   !> sample. Written to a temporary file renamed into place.
   subroutine history_write(model, n, file, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: n
      character(len=*), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, s
      logical :: ok
      character(len=:), allocatable :: tmp
      call check_output_file('HISTORY WRITE', file, error)
      if (allocated(error)) return
      tmp = temporary_name(file)
      open (newunit=u, file=tmp, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call set_error(error, "HISTORY WRITE: cannot write file '"//file//"'")
         return
      end if
      write (u, '(a)') '# udec history '//trim(itoa(n))//': '//trim(hist_keyword(model%hist%kind(n)))
      if (len(model%heading) > 0) write (u, '(a)') '# '//model%heading
      write (u, '(a,a,1x,a)') '# measured at', fmt_real(model%hist%px(n), 16, 8), &
         fmt_real(model%hist%py(n), 16, 8)
      write (u, '(a)') '# time value'
      ! the samples the variable has (a HISTORY given later starts later)
      do s = int(history_first(model%hist, n)), int(model%hist%nsample)
         write (u, '(es23.15e3,1x,es23.15e3)') model%hist%time(s), model%hist%values(n, s)
      end do
      close (u)
      call file_rename(tmp, file, ok)
      if (.not. ok) then
         call file_delete(tmp)        ! no temporary is left behind
         call set_error(error, "HISTORY WRITE: cannot write file '"//file//"'")
      end if
   end subroutine history_write

   !> Contact c joins a block of material m1 to one of material m2 (either
   !> way round): the joints INTERFACE m1 m2 selects (RESET, CHANGE).
   pure logical function between_materials(geo, c, m1, m2)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      integer, intent(in) :: m1, m2
      integer(ip) :: ma, mb
      ma = geo%blocks%material(geo%contacts%block1(c))
      mb = geo%blocks%material(geo%contacts%block2(c))
      between_materials = (ma == m1 .and. mb == m2) .or. (ma == m2 .and. mb == m1)
   end function between_materials

   !> RESET keyword ...
   subroutine do_reset(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, m1, m2, mat
      integer(ip) :: b, c, z
      logical :: iface, stress_done
      associate (model => ctx%model, out => ctx%out)
         iface = .false.
         stress_done = .false.
         m1 = 0; m2 = 0; mat = 0
         ! MAT n and INTERFACE m1 m2 select for the STRESS keyword after them
         ! (manual 4.5); given after it they would be silently ignored and all
         ! stresses lost
         k = parsed%find('STRESS')
         if (k > 0) then
            if (parsed%find('MAT') > k .or. parsed%find('INTERFACE') > k) then
               call set_error(error, 'RESET: MAT n and INTERFACE m1 m2 must precede STRESS ' &
                              //'(e.g. RESET MAT 1 STRESS); nothing reset')
               return
            end if
         end if
         associate (geo => model%geometry)
            do k = 1, parsed%nitems
               select case (parsed%items(k)%name)
               case ('DISP')
                  do b = 1, geo%blocks%n
                     geo%blocks%ux(b) = 0.0_wp
                     geo%blocks%uy(b) = 0.0_wp
                  end do
                  do c = 1, geo%corners%n
                     geo%corners%ux(c) = 0.0_wp
                     geo%corners%uy(c) = 0.0_wp
                  end do
                  ! the gridpoints of FDEF blocks (manual: "All displacements of
                  ! gridpoints of FDEF blocks are set to zero")
                  do c = 1, geo%gridpoints%n
                     geo%gridpoints%ux(c) = 0.0_wp
                     geo%gridpoints%uy(c) = 0.0_wp
                  end do
               case ('JDISP')
                  do c = 1, geo%contacts%n
                     geo%contacts%state%us(c) = 0.0_wp
                  end do
               case ('TIME')
                  model%mech%time = 0.0_wp
               case ('ROTA')
                  do b = 1, geo%blocks%n
                     geo%blocks%rot(b) = 0.0_wp
                  end do
               case ('HIST')
                  call history_clear(model%hist)
               case ('THIST')
                  if (allocated(model%thermal)) model%thermal%nsamp = 0
               case ('INTERFACE')
                  iface = .true.
                  m1 = parsed%int_at(k, 1)
                  m2 = parsed%int_at(k, 2)
               case ('MAT')
                  mat = parsed%int_at(k, 1)
               case ('STRESS')
                  stress_done = .true.
                  ! zone stresses of FDEF blocks: all, or those of blocks of
                  ! material MAT n; none when only INTERFACE m1 m2 selects joints
                  if (mat > 0 .or. .not. iface) then
                     do z = 1, geo%zones%n
                        if (.not. geo%zones%live(z)) cycle
                        if (mat > 0) then
                           if (geo%blocks%material(geo%zones%block(z)) /= mat) cycle
                        end if
                        geo%zones%sxx(z) = 0.0_wp
                        geo%zones%sxy(z) = 0.0_wp
                        geo%zones%syy(z) = 0.0_wp
                        geo%zones%szz(z) = 0.0_wp
                     end do
                  end if
                  ! joints: all, or those of INTERFACE m1 m2; none when only MAT n
                  ! selects blocks
                  if (mat > 0 .and. .not. iface) cycle
                  do c = 1, geo%contacts%n
                     if (.not. geo%contacts%live(c)) cycle
                     if (iface) then
                        if (.not. between_materials(geo, c, m1, m2)) cycle
                     end if
                     geo%contacts%state%fn(c) = 0.0_wp
                     geo%contacts%state%fs(c) = 0.0_wp
                  end do
               end select
            end do
         end associate
         if ((mat > 0 .or. iface) .and. .not. stress_done) &
            call out%line('Note: RESET MAT / INTERFACE select what a STRESS keyword after them ' &
                          //'resets; no STRESS given, no stress reset')
         call out%line('RESET done')
      end associate
   end subroutine do_reset

   !> CHANGE <range> keywords: block MAT / CONS for blocks with centroids in
   !> the range; JMAT / JCONS for contacts in the range, optionally only at
   !> joint orientations ANGLE a1 a2 or between block materials INTERFACE m1 m2.
   subroutine do_change(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, jc
      integer(ip) :: b, c, nb, nc, nzoned
      logical :: ok, has_angle, has_iface, joint, block
      real(wp) :: a1, a2, ang
      integer :: m1, m2
      character(len=120) :: text
      associate (model => ctx%model, out => ctx%out)
         has_angle = .false.; has_iface = .false.; joint = .false.; block = .false.
         a1 = 0.0_wp; a2 = 0.0_wp; m1 = 0; m2 = 0
         do k = 1, parsed%nitems
            select case (parsed%items(k)%name)
            case ('SDEF')
               block = .true.
            case ('FDEF')
               block = .true.
            case ('ANGLE')
               has_angle = .true.
               a1 = parsed%real_at(k, 1)
               a2 = parsed%real_at(k, 2)
               if (abs(a1) >= 180.0_wp .or. abs(a2) >= 180.0_wp .or. a1 > a2) then
                  call set_error(error, 'CHANGE ANGLE: expected a1 <= a2 with |a1|, |a2| < 180')
                  return
               end if
            case ('INTERFACE')
               has_iface = .true.
               m1 = parsed%int_at(k, 1)
               m2 = parsed%int_at(k, 2)
            case ('JCONS')
               jc = parsed%int_at(k, 1)
               call check_known('CHANGE JCONS: unknown joint', jc, known_jcons, error)
               if (allocated(error)) return
               joint = .true.
            case ('JMAT')
               joint = .true.
            case ('CONS')
               call check_known('CHANGE CONS: unknown block', parsed%int_at(k, 1), [0, 1, 3, 4], &
                                error)
               ! CONS 2 is the joint law's number (JCONS 2); a simply-deformable
               ! block is the keyword SDEF (manual Section 4, CHANGE)
               if (allocated(error)) then
                  if (parsed%int_at(k, 1) == 2) error%message = error%message// &
                     ' (a simply-deformable block is CHANGE SDEF; JCONS 2 is the joint law)'
                  return
               end if
               block = .true.
            case ('MAT')
               block = .true.
            end select
         end do
         if ((has_angle .or. has_iface) .and. .not. joint) then
            call set_error(error, 'CHANGE: ANGLE and INTERFACE select joints; give JMAT or JCONS after them')
            return
         end if
         if (parsed%find('SDEF') > 0 .and. parsed%find('FDEF') > 0) then
            call set_error(error, 'CHANGE: give SDEF or FDEF, not both')
            return
         end if
         if (.not. (joint .or. block)) then
            call set_error(error, 'CHANGE: expected MAT, CONS, FDEF, JMAT or JCONS')
            return
         end if
         ! CONS 4 (Griffith fracture) is for SDEF blocks: refused on zoned blocks
         ! before anything changes (CYCLE refuses a zoned block with CONS 4 too)
         k = parsed%find('CONS')
         if (k > 0) then
            if (parsed%int_at(k, 1) == 4) then
               associate (bl => model%geometry%blocks)
                  do b = 1, bl%n
                     if (.not. bl%live(b)) cycle
                     if (.not. parsed%range%contains_point(bl%xc(b), bl%yc(b))) cycle
                     if (bl%fdef(b) .and. bl%nzone(b) > 0) then
                        call set_error(error, 'CHANGE CONS 4: Griffith fracture is for SDEF blocks '// &
                                       'only; block '//trim(itoa(int(b)))//' in the range is zoned '// &
                                       '(FDEF), whose zones know CONS 0, 1, 3')
                        return
                     end if
                  end do
               end associate
               call out%line('note: CONS 4 acts on SDEF blocks only; rigid blocks ignore ' // &
                             'their CONS')
            end if
         end if
         nb = 0
         nc = 0
         nzoned = 0
         associate (geo => model%geometry)
            if (joint) call geometry_refresh(geo)
            do k = 1, parsed%nitems
               select case (parsed%items(k)%name)
               case ('MAT', 'CONS', 'FDEF', 'SDEF')
                  do b = 1, geo%blocks%n
                     if (.not. geo%blocks%live(b)) cycle
                     if (.not. parsed%range%contains_point(geo%blocks%xc(b), &
                        geo%blocks%yc(b))) cycle
                     if (parsed%items(k)%name == 'SDEF') then
                        if (geo%blocks%fdef(b)) then   ! a zoned block stays zoned
                           nzoned = nzoned + 1
                           cycle
                        end if
                        if (.not. geo%blocks%sdef(b)) then
                           call block_sdef_fields(geo%blocks)
                           geo%blocks%sdef(b) = .true.
                           geo%blocks%exx(b) = 0.0_wp; geo%blocks%eyy(b) = 0.0_wp
                           geo%blocks%exy(b) = 0.0_wp; geo%blocks%dxx(b) = 0.0_wp
                           geo%blocks%dyy(b) = 0.0_wp; geo%blocks%dxy(b) = 0.0_wp
                           geo%blocks%sxx(b) = 0.0_wp; geo%blocks%syy(b) = 0.0_wp
                           geo%blocks%sxy(b) = 0.0_wp; geo%blocks%bstate(b) = 0
                           geo%blocks%qxx(b) = 0.0_wp; geo%blocks%qyy(b) = 0.0_wp
                           geo%blocks%qxy(b) = 0.0_wp
                        end if
                     else if (parsed%items(k)%name == 'FDEF') then
                        geo%blocks%sdef(b) = .false.
                        geo%blocks%fdef(b) = .true.   ! zoned by GENERATE
                     else if (parsed%items(k)%name == 'MAT') then
                        geo%blocks%material(b) = parsed%int_at(k, 1)
                     else
                        geo%blocks%cons(b) = parsed%int_at(k, 1)
                     end if
                     nb = nb + 1
                  end do
               case ('JMAT', 'JCONS')
                  do c = 1, geo%contacts%n
                     if (.not. geo%contacts%live(c)) cycle
                     if (.not. parsed%range%contains_point(geo%contacts%x(c), geo%contacts%y(c))) &
                        cycle
                     if (has_angle) then
                        ! joint direction (contact tangent) in (-90, 90]
                        ang = atan2(geo%contacts%nx(c), -geo%contacts%ny(c))*deg
                        if (ang > 90.0_wp) ang = ang - 180.0_wp
                        if (ang <= -90.0_wp) ang = ang + 180.0_wp
                        ok = (ang >= a1 .and. ang <= a2) .or. (ang - 180.0_wp >= a1 .and. ang - 180.0_wp <= a2) &
                             .or. (ang + 180.0_wp >= a1 .and. ang + 180.0_wp <= a2)
                        if (.not. ok) cycle
                     end if
                     if (has_iface) then
                        if (.not. between_materials(geo, c, m1, m2)) cycle
                     end if
                     if (parsed%items(k)%name == 'JMAT') then
                        geo%contacts%jmat(c) = parsed%int_at(k, 1)
                     else
                        geo%contacts%jcons(c) = int(parsed%int_at(k, 1), i1)
                     end if
                     nc = nc + 1
                  end do
               end select
            end do
         end associate
         write (text, '(a,i0,a,i0,a)') 'CHANGE: ', nb, ' block and ', nc, ' contact assignment(s)'
         call out%line(trim(text))
         if (nzoned > 0) then
            write (text, '(a,i0,a)') 'CHANGE SDEF: ', nzoned, &
               ' zoned (FDEF) block(s) in the range ' &
               //'stay zoned'
            call out%line(trim(text))
         end if
      end associate
   end subroutine do_change

   !> Constitutive number n is one of `known`, else the error
   !> "<what> constitutive number n; known: a, b, ..".
   subroutine check_known(what, n, known, error)
      character(len=*), intent(in) :: what
      integer, intent(in) :: n, known(:)
      type(error_t), allocatable, intent(inout) :: error
      character(len=:), allocatable :: list
      integer :: j
      if (any(known == n)) return
      list = itoa(known(1))
      do j = 2, size(known)
         list = list//', '//itoa(known(j))
      end do
      call set_error(error, what//' constitutive number '//trim(itoa(n))//'; known: '//list)
   end subroutine check_known

   !> SET CSCAN / DSCAN / UPCON / OVTOL / CLEMIN (keyword k of `parsed`).
   subroutine set_mechanics_keyword(model, parsed, k)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      call parsed%take(k, 'CSCAN', model%mech%cscan)
      call parsed%take(k, 'DSCAN', model%mech%dscan)
      call parsed%take(k, 'UPCON', model%mech%nupcon)
      call parsed%take(k, 'OVTOL', model%mech%ovtol)
      call parsed%take(k, 'CLEMIN', model%mech%clemin)
   end subroutine set_mechanics_keyword


   pure function rtoa(r) result(s)
      real(wp), intent(in) :: r
      character(len=16) :: s
      s = adjustl(fmt_real(r, 12, 5))
   end function rtoa

   subroutine run_cycle(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cycles_checked(ctx, 'CYCLE', int(parsed%int_at(1, 1), i8), error)
   end subroutine run_cycle

   !> n cycles of CYCLE or SOLVE (`name`), after the checks both share.
   subroutine cycles_checked(ctx, name, ncycles, error, solve)
      type(context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: name
      integer(i8), intent(in) :: ncycles
      type(error_t), allocatable, intent(out) :: error
      type(solve_t), intent(inout), optional :: solve
      logical :: searched
      ! the histories keep every sample: refuse a CYCLE whose samples cannot
      ! be held (manual 4.5, CYCLE: memory for histories is allocated when
      ! CYCLE is executed)
      if (ctx%model%hist%n > 0) then
         call check_request(name//': history samples', &
                            real(ctx%model%hist%nsample, wp) + real(ncycles, wp)/ &
                            real(max(1, ctx%model%hist%ncyc), wp), &
                            real(8*ctx%model%hist%n + 12, wp), real(huge(1_ip) - 1, wp), error)
         if (allocated(error)) return
      end if
      call remove_partial_cracks_once(ctx%model, ctx%out)
      ! a cut on a cycled model: the refresh updates the contacts in place
      ! with a search at the contact margin (of the pairs with a block the
      ! cuts changed when the last search otherwise stands: search_base);
      ! the CYCLE's opening scan takes it as its search (cycle_prepare).
      ! Domains a dry CYCLE gave back stay so (its set-up would give them back
      ! again: contact_domains' domain_release) when the contacts are current:
      ! then the refresh would not search either
      searched = .false.
      if (.not. (domains_released(ctx%model%geometry) .and. ctx%model%geometry%contacts_valid &
                 .and. .not. allocated(ctx%model%fluid))) &
         call geometry_refresh(ctx%model%geometry, searched=searched, since=search_base(ctx%model))
      if (ncycles > 0) call note_zoneless_stress_histories(ctx%model, ctx%out, name)
      call cycle_run(ctx%model, ncycles, ctx%out, error, ctx%cycle, solve, searched)
      ! the engine names its errors CYCLE:; say the command the user typed
      if (allocated(error) .and. name /= 'CYCLE') then
         if (index(error%message, 'CYCLE: ') == 1) &
            error%message = name//': '//error%message(8:)
      end if
   end subroutine cycles_checked

   !> HISTORY SXX / SXY / SYY read a zone's stress; in a model with no zone
   !> (rigid blocks only) they read 0 at every sample. HISTORY promised "the
   !> nearest zone when cycling": say, at the first CYCLE or SOLVE (`name`)
   !> that samples it, that there is none (camp11: a rigid tunnel's SXX history printed zeros
   !> without a word).
   subroutine note_zoneless_stress_histories(model, out, name)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: list
      integer :: i, n
      n = 0
      associate (h => model%hist, zn => model%geometry%zones)
         if (zn%n > 0) then
            if (any(zn%live(1:zn%n))) return
         end if
         list = ''
         do i = 1, h%n
            if (h%kind(i) /= hist_sxx .and. h%kind(i) /= hist_sxy .and. h%kind(i) /= hist_syy) cycle
            ! once: at the first run that samples it
            if (.not. allocated(h%first_sample)) cycle
            if (i > size(h%first_sample)) cycle
            if (h%first_sample(i) <= h%nsample) cycle
            if (len(list) > 0) list = list//', '
            list = list//itoa(i)//' ('//trim(hist_keyword(h%kind(i)))//')'
            n = n + 1
         end do
      end associate
      if (n == 0) return
      if (n == 1) then
         list = 'history '//list//' reads a zone''s stress'
      else
         list = 'histories '//list//' read zone stresses'
      end if
      call out%line(name//': note: '//list//', and the model has no zones (its blocks are '// &
                    'rigid): 0 is recorded; GENERATE zones blocks (before INSITU), and the '// &
                    'contacts'' stresses are HISTORY NSTR / SSTR')
   end subroutine note_zoneless_stress_histories

   !> SOLVE <RATIO r> <CYCLES n> (an extension, not in the 1989 manual):
   !> CYCLE until the ratio of the maximum unbalanced force to the mean
   !> contact force (engine_cycle, cycle_force_ratio) is below r, at most n
   !> cycles; the ratio is measured at every row (every 10 cycles or HIST
   !> NCYC). Says which ended it: the ratio, the CYCLES limit or Ctrl-C.
   subroutine run_solve(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(solve_t) :: solve
      integer(i8) :: ncycles
      integer :: k
      character(len=320) :: line
      real(wp) :: time0
      real(wp), allocatable :: bux0(:), buy0(:), gux0(:), guy0(:)
      ncycles = solve_default_cycles
      k = parsed%find('RATIO')
      if (k > 0) solve%ratio_limit = parsed%real_at(k, 1)
      k = parsed%find('CYCLES')
      if (k > 0) ncycles = int(parsed%int_at(k, 1), i8)
      ! manual Section 3.6: a static solution needs damping, "otherwise, the
      ! system will oscillate indefinitely"; DAMP is off until given. SOLVE
      ! asks for a static solution, so with no DAMP given it switches on the
      ! manual's damping for one (DAMP AUTO, Sections 2 and 4.5); a damping the
      ! user switched off (DAMP 0) stays off, with the note.
      if (ctx%model%mech%damping == damping_none .and. geometry_live_blocks(ctx%model%geometry) > 0) then
         if (.not. ctx%model%mech%damping_given) then
            ctx%model%mech%damping = damping_auto
            ctx%model%mech%damping_given = .true.
            call ctx%out%line('Note: SOLVE: no DAMP was given: DAMP AUTO is now on (the '// &
                              'damping for static solutions, manual Sections 2 and 4.5; an '// &
                              'undamped model oscillates and never balances, Section 3.6); '// &
                              'DAMP 0 switches damping off')
         else
            call ctx%out%line('Note: SOLVE: the model has no damping (DAMP 0): an '// &
                              'undamped model oscillates and may never balance (manual '// &
                              'Section 3.6); give DAMP AUTO before SOLVE for a static solution')
         end if
      end if
      ! where every block and gridpoint stood, to tell a loose block from a
      ! settling model if the SOLVE does not balance (note_moving_free)
      associate (bl => ctx%model%geometry%blocks, gp => ctx%model%geometry%gridpoints)
         time0 = ctx%model%mech%time
         bux0 = bl%ux(1:bl%n)
         buy0 = bl%uy(1:bl%n)
         gux0 = gp%ux(1:gp%n)
         guy0 = gp%uy(1:gp%n)
      end associate
      call cycles_checked(ctx, 'SOLVE', ncycles, error, solve)
      if (allocated(error)) return
      if (solve%unheld) then
         call ctx%out%line('SOLVE: not run: nothing holds the model and its loads do not '// &
                           'balance (the note above), so it would accelerate as one body '// &
                           'without end and never come to rest; hold it (FIX, BOUND XVEL / '// &
                           'YVEL 0) or balance its loads; CYCLE n runs it as it is')
         return
      else if (solve%idle) then
         write (line, '(a,i0,3a)') 'SOLVE: nothing to balance (stopped after ', solve%cycles, &
            ' cycles): a balanced model with zero applied force: no contact carries a force '// &
            'above round-off (', trim(adjustl(fmt_real(solve%floor, 11, 4))), &
            '), nothing weighs or is stressed, and no unbalanced force acts above it '// &
            '(is every block FIXed, or no load given?)'
      else if (solve%reached) then
         write (line, '(a,i0,4a)') 'SOLVE: balanced after ', solve%cycles, &
            ' cycles: force ratio ', trim(adjustl(fmt_real(solve%ratio, 11, 4))), ' < RATIO ', &
            trim(adjustl(fmt_real(solve%ratio_limit, 11, 4)))
      else if (solve%interrupted) then
         write (line, '(a,i0,2a)') 'SOLVE: interrupted after ', solve%cycles, &
            ' cycles: force ratio ', trim(ratio_text(solve%ratio))
      else
         write (line, '(a,i0,5a)') 'SOLVE: not balanced: the CYCLES limit (', ncycles, &
            ') ended it with force ratio ', trim(ratio_text(solve%ratio)), ' >= RATIO ', &
            trim(adjustl(fmt_real(solve%ratio_limit, 11, 4)))
         if (solve%ratio < 0.0_wp) line = trim(line)//' (no contact carries a force and '// &
                                          'nothing weighs or is stressed: the ratio is undefined)'
      end if
      call ctx%out%line(trim(line))
      if (.not. (solve%reached .or. solve%interrupted .or. solve%idle)) then
         call note_moving_free()
         call note_light_masses()
         call note_stiff_joints()
      end if
   contains
      !> A SOLVE that did not balance in a zoned model whose joints are far
      !> stiffer than its zones: the step is set by the joints, and the zones'
      !> own deformation needs about sqrt(contrast) times as many cycles. A new
      !> user's tunnel with JKN 1E14 in blocks of K 1E8 (round 12,
      !> docs/closed_form.md) ended 100 000 cycles at force ratio 4.6 without
      !> a word on why.
      subroutine note_stiff_joints()
         !> joint stiffness x zone width over the zones' modulus above which
         !> the note is given (rock: JKN 1E10, 1 m zones, K + 4G/3 3E10: 0.3)
         real(wp), parameter :: contrast_noted = 1.0e3_wp
         integer(ip) :: b, nz, m
         real(wp) :: kj, modulus, area, width, contrast
         character(len=16) :: times, cycles_more
         nz = 0
         area = 0.0_wp
         modulus = 0.0_wp
         associate (bl => ctx%model%geometry%blocks, mats => ctx%model%materials)
            do b = 1, bl%n
               if (.not. bl%live(b) .or. bl%nzone(b) <= 0) cycle
               nz = nz + bl%nzone(b)
               area = area + bl%area(b)
               m = bl%material(b)
               modulus = max(modulus, mats%get(int(m), prop_bulk) + 4.0_wp/3.0_wp*mats%get(int(m), prop_shear))
            end do
            if (nz == 0 .or. .not. modulus > 0.0_wp) return
            kj = 0.0_wp
            do m = 1, mats%nmat
               kj = max(kj, mats%get(int(m), prop_jkn), mats%get(int(m), prop_jks))
            end do
         end associate
         width = sqrt(area/real(nz, wp))
         contrast = kj*width/modulus
         if (.not. contrast > contrast_noted) return
         write (times, '(i0)') nint(min(contrast, 1.0e9_wp))
         write (cycles_more, '(i0)') nint(min(sqrt(contrast), 1.0e9_wp))
         call ctx%out%line('Note: SOLVE: the joints are '//trim(times)// &
                           ' times stiffer than the zones (JKN or JKS '//trim(adjustl(fmt_real(kj, 10, 3)))// &
                           ' x zone width '//trim(adjustl(fmt_real(width, 10, 3)))//' against K + 4G/3 = '// &
                           trim(adjustl(fmt_real(modulus, 10, 3)))//'): the joints set the time step and '// &
                           'the blocks'' deformation needs about '// &
                           trim(cycles_more)//' times as many cycles to '// &
                           'settle; joints about ten times stiffer than the zones (JKN about 10 (K + '// &
                           '4G/3) / zone width) are stiff enough and balance far sooner')
      end subroutine note_stiff_joints

      !> A SOLVE that did not balance because a block (or a gridpoint of a
      !> zoned one) slides or falls free, not because the model settles
      !> slowly: the entity that moved farthest in this SOLVE still moves at
      !> least half as fast as its mean speed over it (a settling model has
      !> slowed far below its mean; a falling block goes faster than its
      !> mean), and it moved more than 1e-2 of its block's size, in a SOLVE of
      !> 1000 cycles or more (a model starting from rest speeds up at first). Random
      !> jointed tunnels (tools/jointed_tunnel_fuzz.py, seed 14) ended 40 000
      !> cycles with a roof wedge falling at 0.2 m/s and only the light-mass
      !> note, whose remedy (MSCALE) cannot balance a falling block.
      subroutine note_moving_free()
         integer(ip) :: i, b, g, nb, ng
         real(wp) :: d, db, dg, v, span, x, y
         character(len=60) :: what
         span = ctx%model%mech%time - time0
         if (.not. (span > 0.0_wp) .or. solve%cycles < 1000) return
         associate (bl => ctx%model%geometry%blocks, gp => ctx%model%geometry%gridpoints)
            nb = min(bl%n, size(bux0))
            ng = min(gp%n, size(gux0))
            call farthest(bl%ux(1:nb) - bux0(1:nb), bl%uy(1:nb) - buy0(1:nb), &
                          [(unzoned_block(ctx%model%geometry, i), i = 1, nb)], b, db)
            call farthest(gp%ux(1:ng) - gux0(1:ng), gp%uy(1:ng) - guy0(1:ng), logical(gp%live(1:ng)), &
                          g, dg)
            if (g > 0 .and. dg > db) then
               d = dg
               v = hypot(gp%vx(g), gp%vy(g))
               x = gp%x(g)
               y = gp%y(g)
               i = gp%block(g)
               what = 'gridpoint '//itoa(g)//' (block '//itoa(i)//')'
            else if (b > 0) then
               d = db
               v = hypot(bl%vx(b), bl%vy(b))
               x = bl%xc(b)
               y = bl%yc(b)
               i = b
               what = 'block '//itoa(b)
            else
               return
            end if
            if (i < 1 .or. i > bl%n) return
            if (.not. (d > 1.0e-2_wp*sqrt(abs(bl%area(i))))) return
            if (.not. (v*span >= 0.5_wp*d)) return
         end associate
         call ctx%out%line('Note: SOLVE: '//trim(what)//' at ('//trim(rtoa(x))//', '// &
                           trim(rtoa(y))//') moved '//trim(rtoa(d))//' in this SOLVE and '// &
                           'still moves at '//trim(rtoa(v))//' (length/time), as fast as '// &
                           'on average or faster: it slides or falls free rather than '// &
                           'settling (a loose key block, a wedge on a weak joint), and no '// &
                           'number of cycles balances it; hold it (FIX, REINFORCE, '// &
                           'STRUCTURE), DELETE it, or follow its fall with CYCLE')
      end subroutine note_moving_free

      !> The entry (`far`, 0 if none) of the largest displacement (dx, dy)
      !> among those in `use`, and that displacement `dist`.
      subroutine farthest(dx, dy, use, far, dist)
         real(wp), intent(in) :: dx(:), dy(:)
         logical, intent(in) :: use(:)
         integer(ip), intent(out) :: far
         real(wp), intent(out) :: dist
         integer(ip) :: j
         far = 0
         dist = 0.0_wp
         do j = 1, size(dx)
            if (.not. use(j)) cycle
            if (hypot(dx(j), dy(j)) > dist) then
               dist = hypot(dx(j), dy(j))
               far = j
            end if
         end do
      end subroutine farthest

      !> A static solution that did not balance on a grid whose lightest
      !> gridpoints, or among rigid blocks whose lightest block, are far below
      !> the average (slivers zoned finely, a small ROUND, a sliver block
      !> where joints meet at a small angle): their mass sets the step, and
      !> the model needs many more cycles than the rest of it would. The
      !> manual's remedy is MSCALE ON (Section 4.5: "to speed up convergence
      !> of static problems involving very non-uniform grids"); a new user
      !> does not know it. The gridpoints are judged first; the rigid blocks
      !> when the grid says nothing (a rigid 50 m model with a block of 1/4000
      !> of the average mass ran 40 000 cycles unbalanced; MSCALE ON: 780).
      subroutine note_light_masses()
         integer(ip) :: low, b
         real(wp) :: ratio
         logical, allocatable :: rigid(:)
         if (ctx%model%mech%mscale) return
         associate (gp => ctx%model%geometry%gridpoints, bl => ctx%model%geometry%blocks)
            call lightest(gp%mass(1:gp%n), logical(gp%live(1:gp%n)), low, ratio)
            if (low > 0) then
               write (line, '(a,i0,5a,i0,a)') 'Note: SOLVE: the time step is set by the lightest ' &
                  //'gridpoints (gridpoint ', low, ' at (', trim(adjustl(fmt_real(gp%x(low), 11, 4))), &
                  ',', trim(adjustl(fmt_real(gp%y(low), 11, 4))), '), 1/', nint(ratio), &
                  ' of the average mass)'
            else
               rigid = [(unzoned_block(ctx%model%geometry, b), b = 1, bl%n)]
               call lightest(bl%mass(1:bl%n), rigid, low, ratio)
               if (low == 0) return
               write (line, '(a,i0,5a,i0,a)') 'Note: SOLVE: the time step is set by the lightest ' &
                  //'blocks (block ', low, ' at (', trim(adjustl(fmt_real(bl%xc(low), 11, 4))), &
                  ',', trim(adjustl(fmt_real(bl%yc(low), 11, 4))), '), 1/', nint(ratio), &
                  ' of the average mass)'
            end if
         end associate
         call ctx%out%line(trim(line)//': if the model is settling rather than failing, '// &
                           'MSCALE ON scales the masses and balances it in far fewer cycles; '// &
                           'the balanced state does not depend on the masses (manual Section '// &
                           '4.5, MSCALE)')
      end subroutine note_light_masses

      !> The lightest of the masses in `use` and the average over its lightest
      !> (`ratio`), when below `light` of the average (the step then is at
      !> least 5 times shorter than the average's); `low` 0 otherwise. A
      !> mass not yet set (a model zoned after its last CYCLE) or unbounded
      !> says nothing.
      subroutine lightest(mass, use, low, ratio)
         real(wp), intent(in) :: mass(:)
         logical, intent(in) :: use(:)
         integer(ip), intent(out) :: low
         real(wp), intent(out) :: ratio
         real(wp), parameter :: light = 1.0_wp/25.0_wp
         integer(ip) :: i, n
         real(wp) :: msum, mlow
         low = 0
         ratio = 0.0_wp
         n = 0
         msum = 0.0_wp
         mlow = huge(1.0_wp)
         do i = 1, size(mass)
            if (.not. use(i)) cycle
            if (.not. (mass(i) > 0.0_wp .and. mass(i) < huge(1.0_wp))) cycle
            n = n + 1
            msum = msum + mass(i)
            if (mass(i) < mlow) then
               mlow = mass(i)
               low = i
            end if
         end do
         if (n == 0 .or. .not. msum < huge(1.0_wp)) then
            low = 0
         else if (mlow >= light*msum/real(n, wp)) then
            low = 0
         else
            ratio = msum/real(n, wp)/mlow
         end if
      end subroutine lightest

      function ratio_text(r) result(text)
         real(wp), intent(in) :: r
         character(len=:), allocatable :: text
         if (r < 0.0_wp) then
            text = 'undefined'
         else
            text = trim(adjustl(fmt_real(r, 11, 4)))
         end if
      end function ratio_text
   end subroutine run_solve

end module commands_mechanics
