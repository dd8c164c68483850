!> BOUNDARY and INSITU (manual Section 4.5) and PRINT BOUNDARY. The boundary
!> list, the free-surface test and the stress-to-force conversion live in
!> zones_boundary_setup, the per-step kernels in zones_boundary, the state in
!> model_boundary. Each handler checks the whole line before it changes the
!> model. Readings of the manual: docs/zones.md ("Boundary conditions",
!> "Initial stresses"); PRINT layout: docs/print.md.
module commands_boundary
   use commands_address, only: resolve_entity
   use model_address, only: ak_corner
   use core_kinds, only: wp, ip
   use model_properties, only: prop_bulk, prop_density, prop_shear
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real, format_real, itoa
   use core_range, only: range_t, range_box, range_all
   use model_state, only: model_t
   use model_mechanics, only: damping_load_changed
   use model_geometry, only: geometry_t, geometry_live_blocks, joint_state_ud
   use model_zones, only: vfix_x, vfix_y, zone_list_t
   use model_zone_fields, only: principal_stresses
   use model_boundary, only: boundary_t, boundary_table_t, bc_free, bc_stress, bc_velocity, &
                             bc_viscous, vis_x, vis_y, bh_constant, bh_linear, bh_sine, bh_cosine, bh_table1, &
                             boundary_has_traction
   use zones_boundary_setup, only: block_grid_t, block_grid_build, boundary_extend, &
                                   boundary_stress_force, boundary_stress_sides, &
                                   boundary_range_ends, &
                                   boundary_mouth_sides, &
                                   boundary_walk, stress_at, boundary_opening_points
   use contact_refresh, only: geometry_refresh
   use contact_update, only: contact_joint_chains, contact_settle_geometry, contact_margin, &
                             corner_anchor
   use contact_mechanics, only: joint_props_of
   use contact_joint_law, only: joint_props_t
   use contact_insitu, only: pair_couples, zoned_contact_balance
   use zones_boundary, only: boundary_traction_force, boundary_freeze_tractions, &
                             boundary_freeze_point
   use commands_fluid, only: boundary_fluid, boundary_fluid_check, print_boundary_fluid, &
                             insitu_pore_pressures
   use commands_parser, only: parsed_t, item_loose
   use model_ffield, only: ffield_t, ffield_generate, ff_free, ff_stress, ff_velocity
   use zones_models, only: known_cons
   use commands_context, only: context_t, registry_t
   use engine_rigid_velocity, only: rigid_velocity_t, rigid_velocity_present, &
                                    rigid_velocity_build, rigid_velocity_reactions
   implicit none
   private
   public :: register_boundary_commands
   public :: do_boundary, do_insitu, boundary_print, boundary_read_table, boundary_history_name
   public :: boundary_set_fup, do_ffield, ffield_print

   !> Largest magnitude of a number BOUNDARY takes (its squares must not overflow).
   real(wp), parameter :: max_boundary_value = 1.0e15_wp

   !> History keywords and the types that may follow them.
   character(len=*), parameter :: type_words(5) = ['CONSTANT', 'LINEAR  ', 'SINE    ', &
                                                   'COSINE  ', 'FUNCTION']

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_boundary_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('boundary', 'BOundary', '[R]', '', 'Corner ii;XLoad r;YLoad r;XFree;YFree;' // &
                   'STress rrr;XGrad rrr;YGrad rrr;LStress rrrrrrrrr;XVEL r;YVEL r;PP r;PGrad r;' // &
                   'IMPermeable;XVisc;YVisc;Mat q;FField;XMul r;YMul r;HRead qs;' // &
                   'XHistory {Constant,Linear,Sine,COsine,Function} [q];' // &
                   'YHistory {Constant,Linear,Sine,COsine,Function} [q];' // &
                   'History {Constant,Linear,Sine,COsine,Function} [q];CONStant;' // &
                   'Linear;Sine rr;COsine rr;Function', '4.5', &
                   'boundary conditions on the outer boundary in a range', handler=do_boundary)
      call reg%note('XLOAD YLOAD', unit='N')
      call reg%note('STRESS', unit='Pa')
      call reg%note('XGRAD YGRAD', unit='Pa/m')
      call reg%note('XVEL YVEL', unit='m/s')
      call reg%note('PP', unit='Pa')
      call reg%note('PGRAD', unit='Pa/m')
      call reg%add('boundary', 'INsitu', '[R]', '', 'STress rrr;XGrad rrr;YGrad rr[r];NODIS', &
                   '4.5', 'initial stresses in blocks, zones and contacts', handler=do_insitu)
      call reg%note('STRESS', unit='Pa')
      call reg%note('XGRAD YGRAD', unit='Pa/m')
      call reg%add('boundary', 'FField', '', 'r', 'Gen rrq;Mat q;Cons c;OFF;ON;Initialize;INT;' // &
                   'XVel r;YVel r;SXX r;SXY r;XVIsc;YVIsc', '4.5', &
                   'free-field boundaries for dynamic input', handler=do_ffield)
      call reg%note('XVEL YVEL', unit='m/s')
      call reg%note('SXX SXY', unit='Pa')
      call reg%add_set('boundary', 'FUP;-FUP', set_boundary)
   end subroutine register_boundary_commands

   ! ---- BOUNDARY ------------------------------------------------------------------

   !> SET FUP (on, the manual's default) / SET -FUP: how the BOUNDARY STRESS
   !> lines that follow act, as tractions on the current boundary or as
   !> fixed forces (model_boundary). -FUP also fixes the tractions already
   !> given, as forces of the boundary as it is now; FUP leaves fixed forces
   !> fixed (they cannot be told from XLOAD / YLOAD). docs/zones.md.
   subroutine boundary_set_fup(model, on, out)
      type(model_t), intent(inout) :: model
      logical, intent(in) :: on
      type(output_t), intent(inout) :: out
      integer(ip) :: nfrozen
      model%bound%fup = on
      if (on) return
      call boundary_freeze_tractions(model%bound, model%geometry, nfrozen)
      if (nfrozen > 0) call out%line('SET -FUP: the boundary stresses of '//itoa(nfrozen)// &
                                     ' boundary point(s) are now fixed forces (their present '// &
                                     'values)')
   end subroutine boundary_set_fup

   !> BOUNDARY <range | CORNER ic1 ic2> keyword ... (docs/zones.md).
   subroutine do_boundary(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(boundary_t) :: bnd
      type(boundary_table_t) :: tables(2)
      logical :: read_table(2), has_vel, acts
      type(block_grid_t) :: grid
      logical, allocatable :: sel(:), csel(:), opening(:), ext(:)
      integer(ip) :: next_, iext, nopen, nstacked, istacked, nzero, izero
      integer :: k, kc, ks, kl, kxg, kyg, n, htype, hdir
      integer(ip) :: i, c, g, nadded, nsel, pp, pn, nfreed, ifreed, tp, tn, nrigid, irigid, &
                     ic1, ic2
      real(wp) :: s0(3), gx(3), gy(3), fx, fy, freq, tload, sp(3), sn(3)
      logical :: sidestacked
      character(len=:), allocatable :: name, ignored
      character(len=200) :: text

      associate (model => ctx%model, out => ctx%out)
         if (geometry_live_blocks(model%geometry) == 0) then
            call set_error(error, 'BOUNDARY: there are no blocks (give BLOCK first)')
            return
         end if
         ! A stress, load or velocity beyond 1e15 overflows the forces' squares
         ! (BOUND STRESS -10 0 1e300 stopped the Debug build on a floating-point
         ! trap in the gridpoint motion; found by robustness.fuzz_decks)
         k = parsed%beyond(max_boundary_value)
         if (k > 0) then
            write (text, '(es12.4e3)') parsed%values(k)%r
            call set_error(error, 'BOUNDARY: the number '//trim(adjustl(text)) &
                           //' is too large for a stress, load or velocity (at most 1E+15)')
            return
         end if
         kc = parsed%find('CORNER')
         if (kc > 0 .and. parsed%has_range) then
            call set_error(error, 'BOUNDARY: give either a range xl xu yl yu or CORNER ic1 ic2, ' &
                           //'not both')
            return
         end if
         ks = parsed%find('STRESS')
         kl = parsed%find('LSTRESS')
         kxg = parsed%find('XGRAD')
         kyg = parsed%find('YGRAD')
         if (ks > 0 .and. kl > 0) then
            call set_error(error, 'BOUNDARY: give STRESS (with XGRAD / YGRAD) or LSTRESS, not both')
            return
         end if
         if ((kxg > 0 .or. kyg > 0) .and. ks == 0) then
            call set_error(error, 'BOUNDARY XGRAD / YGRAD: they vary the stress of STRESS ' &
                           //'sxx sxy syy given on the same line')
            return
         end if

         ! check the line: history types, tables, keywords without mechanics yet
         read_table = .false.
         ignored = ''
         has_vel = .false.
         acts = .false.
         do k = 1, parsed%nitems
            name = parsed%items(k)%name
            select case (name)
            case ('HREAD')
               n = parsed%int_at(k, 1)
               if (n > 2) then
                  call set_error(error, 'BOUNDARY HREAD: the history number must be 1 or 2')
                  return
               end if
               call boundary_read_table(parsed%text_at(k, 2), tables(n), error)
               if (allocated(error)) then
                  error%message = 'BOUNDARY HREAD: '//error%message
                  return
               end if
               read_table(n) = .true.
               acts = .true.
            case ('XHISTORY', 'YHISTORY', 'HISTORY')
               call history_of(k, htype, freq, tload)
               if (allocated(error)) return
               if (htype >= bh_table1) then
                  n = htype - bh_table1 + 1
                  if (.not. read_table(n) .and. model%bound%table(n)%np == 0) then
                     write (text, '(a,i0,a,i0,a)') 'BOUNDARY '//name//' ', n, &
                        ': history ', n, ' has not been read (give HREAD n file first)'
                     call set_error(error, trim(text))
                     return
                  end if
               end if
               acts = .true.
            case ('CONSTANT', 'LINEAR', 'SINE', 'COSINE', 'FUNCTION')
               if (k == 1) then
                  call set_error(error, 'BOUNDARY '//name//': a history type follows XHISTORY, ' &
                                 //'YHISTORY or HISTORY')
                  return
               end if
               select case (parsed%items(k - 1)%name)
               case ('XHISTORY', 'YHISTORY', 'HISTORY')
               case default
                  call set_error(error, 'BOUNDARY '//name//': a history type follows XHISTORY, ' &
                                 //'YHISTORY or HISTORY')
                  return
               end select
            case ('XVEL', 'YVEL')
               has_vel = .true.
               acts = .true.
            case ('MAT')
               if (parsed%int_at(k, 1) < 1) then
                  call set_error(error, 'BOUNDARY MAT: expected a material number n >= 1 '// &
                                 '(the far-field material of a viscous boundary)')
                  return
               end if
               acts = .true.
            case ('PP', 'PGRAD', 'IMPERMEABLE')
               ! fluid boundary (commands_fluid), below
            case ('FFIELD')
               ! the point is tied to the free field (FFIELD; model_ffield)
               acts = .true.
            case ('', 'CORNER', 'XGRAD', 'YGRAD')
            case default
               acts = .true.
            end select
         end do
         if (len(ignored) > 0) call out%line('*** BOUNDARY'//ignored// &
                                             ': not yet implemented (ignored)')
         call boundary_fluid_check(model, parsed, error)
         if (allocated(error)) return
         if (.not. acts) then
            call boundary_fluid(model, parsed, out)
            return
         end if

         ! the boundary list: built by the first BOUNDARY, extended by new corners
         nopen = 0
         bnd = model%bound
         do n = 1, 2
            if (read_table(n)) bnd%table(n) = tables(n)
         end do
         call block_grid_build(model%geometry, grid)
         call boundary_extend(bnd, model%geometry, grid, nadded)
         allocate (sel(max(1_ip, bnd%n)))
         sel = .false.
         if (kc > 0) then
            ! ic1 ic2: 1989 corner addresses (manual Section 4.5 BOUNDARY)
            call resolve_entity(model, ak_corner, int(parsed%int_at(kc, 1), ip), &
                                'BOUNDARY CORNER', &
                                out, ic1, error)
            if (allocated(error)) return
            call resolve_entity(model, ak_corner, int(parsed%int_at(kc, 2), ip), &
                                'BOUNDARY CORNER', &
                                out, ic2, error)
            if (allocated(error)) return
            call boundary_walk(bnd, model%geometry, grid, ic1, ic2, sel(1:bnd%n), error)
            if (allocated(error)) return
         else if (parsed%range%kind == range_all) then
            ! no range: the outer boundary (manual Section 4.5), not the walls
            ! of openings (zones_boundary_setup's boundary_opening_points)
            allocate (opening(bnd%n))
            call boundary_opening_points(bnd, model%geometry, grid, opening)
            sel(1:bnd%n) = .not. opening
            nopen = count(opening)
         else
            do i = 1, bnd%n
               c = bnd%corner(i)
               sel(i) = parsed%range%contains_point(model%geometry%corners%x(c), &
                                                    model%geometry%corners%y(c))
            end do
         end if
         do i = 1, bnd%n
            c = bnd%corner(i)
            if (.not. model%geometry%corners%live(c)) then
               sel(i) = .false.
            else if (.not. model%geometry%blocks%live(model%geometry%corners%block(c))) then
               sel(i) = .false.
            end if
         end do
         ! XVEL / YVEL on corners of rigid or SDEF blocks constrain their
         ! block's motion (engine_rigid_velocity): Section 4.5 gives the keywords
         ! "for FDEF blocks", Section 6 keeps the boundary record per corner
         ! whatever its block, and thermal Case 4 (Section 7.8.5) gives
         ! `bou -1 6 -1 0.01 yvel 0` over a rigid block; counted for a note
         nrigid = 0
         irigid = 0
         if (has_vel) then
            do i = 1, bnd%n
               if (.not. sel(i)) cycle
               c = bnd%corner(i)
               if (model%geometry%corners%gp(c) == 0) then
                  nrigid = nrigid + 1
                  if (irigid == 0) irigid = c
               end if
            end do
         end if

         ! from here on nothing can fail: apply the keywords in order
         call boundary_fluid(model, parsed, out)
         s0 = 0.0_wp; gx = 0.0_wp; gy = 0.0_wp
         if (ks > 0) s0 = [(parsed%real_at(ks, n), n = 1, 3)]
         if (kxg > 0) gx = [(parsed%real_at(kxg, n), n = 1, 3)]
         if (kyg > 0) gy = [(parsed%real_at(kyg, n), n = 1, 3)]
         if (kl > 0) then
            s0 = [(parsed%real_at(kl, n), n = 1, 3)]
            gx = [(parsed%real_at(kl, n), n = 4, 6)]
            gy = [(parsed%real_at(kl, n), n = 7, 9)]
         end if
         nsel = count(sel(1:bnd%n))
         ! selection by corner id, for the segments a STRESS acts on
         allocate (csel(max(1_ip, model%geometry%corners%n)))
         csel = .false.
         do i = 1, bnd%n
            if (sel(i)) csel(bnd%corner(i)) = .true.
         end do
         ! a STRESS range that stops one segment short of the model's corner
         ! loads its straight edge on to that corner (boundary_range_ends)
         allocate (ext(bnd%n))
         ext = .false.
         if ((ks > 0 .or. kl > 0) .and. kc == 0 .and. parsed%range%kind /= range_all) then
            call boundary_range_ends(bnd, model%geometry, grid, csel, ext)
            ext = ext .and. .not. sel(1:bnd%n)
         end if
         next_ = count(ext)
         iext = 0
         do i = 1, bnd%n
            if (.not. ext(i)) cycle
            csel(bnd%corner(i)) = .true.
            if (iext == 0) iext = i
         end do
         associate (gp => model%geometry%gridpoints, co => model%geometry%corners)
            do k = 1, parsed%nitems
               name = parsed%items(k)%name
               do i = 1, bnd%n
                  if (.not. sel(i)) then
                     if (.not. ext(i) .or. (name /= 'STRESS' .and. name /= 'LSTRESS')) cycle
                  end if
                  c = bnd%corner(i)
                  g = co%gp(c)
                  select case (name)
                  case ('STRESS', 'LSTRESS')
                     if (bnd%fup) then
                        ! tractions on the current boundary (SET FUP, model_boundary)
                        call boundary_stress_sides(model%geometry, grid, c, s0, gx, gy, sp, sn, &
                                                   csel, &
                                                   bnd, tp, tn)
                        ! a side cut short by a T-junction runs to that corner
                        call add_side_stress(.true., tp, sp)
                        call add_side_stress(.false., tn, sn)
                        ! a joint mouth: the gap segment to the neighbouring block
                        call boundary_mouth_sides(bnd, model%geometry, grid, c, s0, gx, gy, csel, &
                                                  pp, pn, sp, sn)
                        if (pp > 0) call add_side_stress(.true., pp, sp)
                        if (pn > 0) call add_side_stress(.false., pn, sn)
                     else
                        ! fixed forces from the present geometry (SET -FUP)
                        call boundary_stress_force(bnd, model%geometry, grid, c, s0, gx, gy, fx, fy, csel)
                        bnd%dfx(i) = bnd%dfx(i) + fx
                        bnd%dfy(i) = bnd%dfy(i) + fy
                        ! and the half of a mouth or T-junction segment to the
                        ! neighbouring block (as under FUP), so the loads close
                        call boundary_mouth_sides(bnd, model%geometry, grid, c, s0, gx, gy, csel, &
                                                  pp, pn, sp, sn)
                        if (pp > 0) call add_segment(sp, co%x(pp) - co%x(c), co%y(pp) - co%y(c), -1.0_wp)
                        if (pn > 0) call add_segment(sn, co%x(pn) - co%x(c), co%y(pn) - co%y(c), 1.0_wp)
                     end if
                     ! a corner the range was extended to keeps its velocities
                     if (sel(i) .or. bnd%ix(i) /= bc_velocity) call set_force_code(i, g, 1)
                     if (sel(i) .or. bnd%iy(i) /= bc_velocity) call set_force_code(i, g, 2)
                  case ('XLOAD')
                     bnd%dfx(i) = bnd%dfx(i) + parsed%real_at(k, 1)
                     call set_force_code(i, g, 1)
                  case ('YLOAD')
                     bnd%dfy(i) = bnd%dfy(i) + parsed%real_at(k, 1)
                     call set_force_code(i, g, 2)
                  case ('XFREE')
                     call free_direction(i, g, 1)
                  case ('YFREE')
                     call free_direction(i, g, 2)
                  case ('MAT')
                     bnd%vmat(i) = parsed%int_at(k, 1)
                  case ('FFIELD')
                     bnd%ff(i) = 1
                  case ('XVISC')
                     bnd%vis(i) = ior(bnd%vis(i), vis_x)
                     call velocity_to_viscous(i, g, 1)
                  case ('YVISC')
                     bnd%vis(i) = ior(bnd%vis(i), vis_y)
                     call velocity_to_viscous(i, g, 2)
                  case ('XVEL')
                     ! the applied load stays stored (fx, dfx): the velocity
                     ! overrides it while it holds, the reaction includes it,
                     ! and XFREE or a STRESS / load brings it back (docs/zones.md)
                     bnd%ix(i) = bc_velocity
                     bnd%vx(i) = parsed%real_at(k, 1)
                     bnd%vis(i) = iand(bnd%vis(i), not(vis_x))
                     if (g > 0) gp%vfix(g) = ior(gp%vfix(g), vfix_x)
                  case ('YVEL')
                     bnd%iy(i) = bc_velocity
                     bnd%vy(i) = parsed%real_at(k, 1)
                     bnd%vis(i) = iand(bnd%vis(i), not(vis_y))
                     if (g > 0) gp%vfix(g) = ior(gp%vfix(g), vfix_y)
                  case ('XMUL')
                     bnd%xmul(i) = parsed%real_at(k, 1)
                  case ('YMUL')
                     bnd%ymul(i) = parsed%real_at(k, 1)
                  case ('XHISTORY', 'YHISTORY', 'HISTORY')
                     call history_of(k, htype, freq, tload)
                     do hdir = 1, 2
                        if (hdir == 1 .and. name == 'YHISTORY') cycle
                        if (hdir == 2 .and. name == 'XHISTORY') cycle
                        if (hdir == 1) then
                           bnd%hx(i) = htype; bnd%freqx(i) = freq; bnd%tloadx(i) = tload
                        else
                           bnd%hy(i) = htype; bnd%freqy(i) = freq; bnd%tloady(i) = tload
                        end if
                     end do
                  end select
               end do
            end do
         end associate
         ! a viscous point needs its far-field material (checked on the copy, so
         ! a rejected line changes nothing)
         if (parsed%find('XVISC') > 0 .or. parsed%find('YVISC') > 0) then
            do i = 1, bnd%n
               if (.not. sel(i)) cycle
               if (bnd%vis(i) /= 0 .and. bnd%vmat(i) == 0) then
                  c = bnd%corner(i)
                  write (text, '(a,i0,5a)') 'BOUNDARY XVISC / YVISC: corner ', c, &
                     ' at (', fmt_real(model%geometry%corners%x(c), 12, 5), ', ', &
                     fmt_real(model%geometry%corners%y(c), 12, 5), &
                     ') has no far-field material: give BOUNDARY MAT n first (or on this line)'
                  call set_error(error, trim(text))
                  return
               end if
            end do
         end if
         ! the history of later SET ZPRESS sources: the last history keyword of the line
         do k = parsed%nitems, 1, -1
            select case (parsed%items(k)%name)
            case ('XHISTORY', 'YHISTORY', 'HISTORY')
               call history_of(k, htype, freq, tload)
               bnd%zp%h_next = htype
               bnd%zp%freq_next = freq
               bnd%zp%tload_next = tload
               exit
            end select
         end do
         ! points where this STRESS adds to a stress already on the same side
         ! (manual Section 4.5, BOUNDARY, Note), noted below with the total;
         ! per-side stresses meeting at a corner are not counted
         nstacked = 0
         istacked = 0
         sidestacked = .true.
         nzero = 0
         izero = 0
         if (zero_stress()) then
            ! STRESS 0 0 0 adds nothing to a stress already there (the
            ! Note's increments): a user who meant to take it off is told
            do i = 1, min(bnd%n, model%bound%n)
               if (.not. sel(i)) cycle
               if (carries(i, .true.) .or. carries(i, .false.)) then
                  nzero = nzero + 1
                  if (izero == 0) izero = i
               end if
            end do
         end if
         if (ks > 0 .or. kl > 0) then
            do i = 1, min(bnd%n, model%bound%n)
               if (.not. sel(i)) cycle
               if (stacked(i, .true.)) then
                  nstacked = nstacked + 1
                  if (istacked == 0) istacked = i
               else if (stacked(i, .false.)) then
                  nstacked = nstacked + 1
                  if (istacked == 0) then
                     istacked = i
                     sidestacked = .false.
                  end if
               end if
            end do
         end if
         ! a STRESS or load that replaces a prescribed velocity (manual Section
         ! 4, BOUNDARY: "STRESS affects all degrees of freedom") is the usual
         ! reason a model corner held by YVEL slides away: say so (XFREE /
         ! YFREE free it as asked, a viscous condition has its own note)
         nfreed = 0
         ifreed = 0
         do i = 1, min(bnd%n, model%bound%n)
            if (.not. sel(i)) cycle
            if ((model%bound%ix(i) == bc_velocity .and. bnd%ix(i) == bc_stress) .or. &
                (model%bound%iy(i) == bc_velocity .and. bnd%iy(i) == bc_stress)) then
               nfreed = nfreed + 1
               if (ifreed == 0) ifreed = i
            end if
         end do
         model%bound = bnd
         if (nsel > 0 .and. (parsed%find('STRESS') > 0 .or. parsed%find('XLOAD') > 0 .or. &
                             parsed%find('YLOAD') > 0)) &
            call damping_load_changed(model%mech, model%geometry%zones%n > 0)
         write (text, '(a,i0,a,i0,a)') 'BOUNDARY: ', nsel, ' of ', model%bound%n, ' boundary points'
         if (nadded > 0 .and. nadded /= model%bound%n) write (text, '(a,a,i0,a)') trim(text), &
            ' (', nadded, ' new)'
         if (nsel == 0) text = trim(text)//'; none lies in the range'
         call out%line(trim(text))
         if (nopen > 0) then
            write (text, '(a,i0,a)') 'note: BOUNDARY: ', nopen, ' point(s) on the walls of openings left ' // &
               'as they are (no range: the outer boundary, manual Section 4.5); a range acts ' // &
               'on them'
            call out%line(trim(text))
         end if
         if (nrigid > 0) then
            write (text, '(a,i0,a,i0,3a)') 'note: BOUNDARY XVEL / YVEL: ', nrigid, &
               ' corner(s) of rigid or SDEF blocks (first ', irigid, ' at ', &
               corner_text(model%geometry, irigid), &
               '): the velocity constrains the motion of their block (a FIXed block stays fixed)'
            call out%line(trim(text))
         end if
         if (nstacked > 0) call note_stacked()
         if (nzero > 0) call note_zero()
         ! (a STRESS added to one already there is an increment: the stacked
         ! note above gives the total, and a positive increment unloads)
         if (ks > 0 .and. kxg == 0 .and. kyg == 0 .and. nsel > 0 .and. nstacked == 0) &
            call note_tensile()
         if (next_ > 0) then
            write (text, '(i0)') next_
            call out%line('note: BOUNDARY STRESS: the range stops one segment short of '//trim(text)// &
                          ' corner(s) of the boundary (first at '// &
                          corner_text(model%geometry, bnd%corner(iext))// &
                          '): its straight edge is loaded on to the corner (that segment had an ' // &
                          'end in each range and no line loaded it)')
         end if
         if (nfreed > 0) then
            write (text, '(a,i0,3a)') 'Warning: BOUNDARY: the stress or load replaces a prescribed ' // &
               'XVEL / YVEL at ', nfreed, ' points (first at ', &
               corner_text(model%geometry, bnd%corner(ifreed)), &
               '): they are free now; give the velocity again after the stress to hold them'
            call out%line(trim(text))
         end if

      end associate
   contains

      !> Did this line add to a stress already on point i's half edge towards
      !> its previous corner (prev) or its next? Under SET -FUP (fixed forces)
      !> prev is the x force and next the y force.
      logical function stacked(i, prev)
         integer(ip), intent(in) :: i
         logical, intent(in) :: prev
         real(wp) :: before(3), after(3)
         call side_change(i, prev, before, after)
         stacked = any(before /= 0.0_wp) .and. any(after /= before)
      end function stacked

      !> Does point i's half edge (as in stacked) carry a stress from before
      !> this line?
      logical function carries(i, prev)
         integer(ip), intent(in) :: i
         logical, intent(in) :: prev
         real(wp) :: before(3), after(3)
         call side_change(i, prev, before, after)
         carries = any(before /= 0.0_wp)
      end function carries

      !> The stress (or, under SET -FUP, the force) on point i's half edge
      !> before this line and after it.
      subroutine side_change(i, prev, before, after)
         integer(ip), intent(in) :: i
         logical, intent(in) :: prev
         real(wp), intent(out) :: before(3), after(3)
         integer(ip) :: e
         if (bnd%fup) then
            before = side_total(ctx%model%bound, i, prev)
            after = side_total(bnd, i, prev)
            ! a joint's mouth closed at this point (the other block's corner
            ! here): its gap, of length 0, carries none of the stress
            e = bnd%end_next(i)
            if (prev) e = bnd%end_prev(i)
            if (e > 0) then
               if (.not. apart(bnd%corner(i), e)) before = 0.0_wp
            end if
         else if (prev) then
            before = [ctx%model%bound%fx(i) + ctx%model%bound%dfx(i), 0.0_wp, 0.0_wp]
            after = [bnd%fx(i) + bnd%dfx(i), 0.0_wp, 0.0_wp]
         else
            before = [ctx%model%bound%fy(i) + ctx%model%bound%dfy(i), 0.0_wp, 0.0_wp]
            after = [bnd%fy(i) + bnd%dfy(i), 0.0_wp, 0.0_wp]
         end if
      end subroutine side_change

      !> The line's STRESS is 0 0 0 with no gradient (nor LSTRESS, load or
      !> history): on points that carry a stress it changes nothing.
      logical function zero_stress()
         integer :: j
         zero_stress = .false.
         if (ks == 0 .or. kl > 0) return
         if (parsed%find('XLOAD') > 0 .or. parsed%find('YLOAD') > 0) return
         do j = 1, 3
            if (parsed%real_at(ks, j) /= 0.0_wp) return
            if (kxg > 0) then
               if (parsed%real_at(kxg, j) /= 0.0_wp) return
            end if
            if (kyg > 0) then
               if (parsed%real_at(kyg, j) /= 0.0_wp) return
            end if
         end do
         zero_stress = .true.
      end function zero_stress

      !> BOUNDARY STRESS 0 0 0 on points that carry a stress: a new user
      !> releasing a top stress (camp10 deck: `BOUND .. STRESS 0 0 0` after
      !> `STRESS 0 0 -1E6` and a CYCLE) kept the whole load, silently. Say
      !> that it adds nothing and how to take the stress off.
      subroutine note_zero()
         real(wp) :: st(3)
         character(len=400) :: line
         logical :: prev
         i = izero
         write (line, '(a,i0,a,i0,3a)') 'note: BOUNDARY STRESS 0 0 0 changes nothing on ', nzero, &
            ' of the ', nsel, ' points: they carry a stress already and a stress given is ' // &
            'added to it (manual Section 4.5, BOUNDARY, Note: stresses are increments); at ', &
            corner_text(ctx%model%geometry, ctx%model%bound%corner(i)), ' it is'
         if (ctx%model%bound%fup) then
            prev = carries(i, .true.)
            st = side_total(ctx%model%bound, i, prev)
            line = trim(line)//' sxx '//trim(format_real(st(1)))//', sxy '// &
                   trim(format_real(st(2)))//', syy '//trim(format_real(st(3)))// &
                   '; to take it off give its opposite (STRESS '// &
                   trim(format_real(-st(1)))//' '//trim(format_real(-st(2)))//' '// &
                   trim(format_real(-st(3)))//')'
         else
            line = trim(line)//' the force ('// &
                   trim(format_real(ctx%model%bound%fx(i) + ctx%model%bound%dfx(i)))//', '// &
                   trim(format_real(ctx%model%bound%fy(i) + ctx%model%bound%dfy(i)))// &
                   '); to take it off give the opposite stress'
         end if
         call ctx%out%line(trim(line))
      end subroutine note_zero

      !> BOUNDARY STRESS given on points that carry one already adds to it
      !> (manual Section 4.5, BOUNDARY, Note: a change "must be input as a
      !> stress incremental change"); a user who meant to replace it has
      !> doubled the load. Name the count and the total now on the first one.
      subroutine note_stacked()
         real(wp) :: st(3)
         character(len=400) :: line
         i = istacked
         write (line, '(a,i0,a,i0,3a)') 'note: BOUNDARY STRESS adds to the boundary stress ' // &
            'already on ', nstacked, ' of the ', nsel, ' points (manual Section 4.5, BOUNDARY, ' // &
            'Note: stresses are increments); at ', &
            corner_text(ctx%model%geometry, ctx%model%bound%corner(i)), ' it is now'
         if (ctx%model%bound%fup) then
            ! on the half edge found stacked: total plus this CYCLE's increment
            st = side_total(ctx%model%bound, i, sidestacked)
            line = trim(line)//' sxx '//trim(format_real(st(1)))//', sxy '// &
                   trim(format_real(st(2)))//', syy '//trim(format_real(st(3)))
         else
            line = trim(line)//' the force ('// &
                   trim(format_real(ctx%model%bound%fx(i) + ctx%model%bound%dfx(i)))//', '// &
                   trim(format_real(ctx%model%bound%fy(i) + ctx%model%bound%dfy(i)))//')'
         end if
         line = trim(line)//'; to replace a stress give the difference'
         call ctx%out%line(trim(line))
      end subroutine note_stacked

      !> BOUNDARY STRESS whose largest principal stress is tensile (stresses
      !> are positive in tension, manual Section 4.1): a rock mass held by a
      !> far field is in compression, so this is most often a sign slip, which
      !> pulls the boundary blocks off a jointed model (a new user's `BOUND
      !> STRESS 5e6 0 10e6` ended on Contact Overlap Too Great among blocks
      !> flying apart). A note, not an error: a tension test means it. None for
      !> a pure shear stress (sxx = syy = 0: its principal stresses are +-sxy
      !> whatever the sign) nor for a stress given with a history (a dynamic
      !> input, SINE, COSINE or a table, swings through both signs; a LINEAR
      !> ramp of a far field still gets it): a new user's
      !> S wave `BOUND STRESS 0 1E5 0 XHIS SINE 50 0.01` got the note.
      subroutine note_tensile()
         real(wp) :: s3, s1, angle
         if (parsed%real_at(ks, 1) == 0.0_wp .and. parsed%real_at(ks, 3) == 0.0_wp) return
         if (parsed%find('SINE') > 0 .or. parsed%find('COSINE') > 0 .or. table('XHISTORY') .or. &
             table('YHISTORY') .or. table('HISTORY')) return
         call principal_stresses(parsed%real_at(ks, 1), parsed%real_at(ks, 3), parsed%real_at(ks, 2), &
                                 s3, s1, angle)
         if (.not. s1 > 0.0_wp) return
         call ctx%out%line('note: BOUNDARY STRESS: the stress pulls on the boundary (largest principal '// &
                       'stress '//trim(format_real(s1))//' tensile: stresses are positive in '// &
                       'tension, manual Section 4.1); a rock mass under a far-field load wants '// &
                       'negative (compressive) values')
      end subroutine note_tensile

      !> Does the history keyword name come with a table number (HREAD)?
      logical function table(name)
         character(len=*), intent(in) :: name
         integer :: k
         k = parsed%find(name)
         table = .false.
         if (k > 0) table = parsed%items(k)%count > 0
      end function table

      !> Are corners a and b at different places?
      logical function apart(a, b)
         integer(ip), intent(in) :: a, b
         apart = ctx%model%geometry%corners%x(a) /= ctx%model%geometry%corners%x(b) .or. &
                 ctx%model%geometry%corners%y(a) /= ctx%model%geometry%corners%y(b)
      end function apart

      !> Stress (sxx, sxy, syy) on the half edge of point ip0 towards its
      !> previous (prev) or next corner: the total plus the next CYCLE's increment.
      function side_total(b, ip0, prev) result(st)
         type(boundary_t), intent(in) :: b
         integer(ip), intent(in) :: ip0
         logical, intent(in) :: prev
         real(wp) :: st(3)
         if (prev) then
            st = [b%sxx_prev(ip0) + b%dsxx_prev(ip0), b%sxy_prev(ip0) + b%dsxy_prev(ip0), &
                  b%syy_prev(ip0) + b%dsyy_prev(ip0)]
         else
            st = [b%sxx_next(ip0) + b%dsxx_next(ip0), b%sxy_next(ip0) + b%dsxy_next(ip0), &
                  b%syy_next(ip0) + b%dsyy_next(ip0)]
         end if
      end function side_total

      !> Stress increment ds (sxx, sxy, syy) on the side of point i towards
      !> its previous corner (prev) or its next one; a corner `last` > 0 is
      !> where that side now ends (a T-junction, a joint mouth).
      subroutine add_side_stress(prev, last, ds)
         logical, intent(in) :: prev
         integer(ip), intent(in) :: last
         real(wp), intent(in) :: ds(3)
         if (prev) then
            if (last > 0) bnd%end_prev(i) = last
            bnd%dsxx_prev(i) = bnd%dsxx_prev(i) + ds(1)
            bnd%dsxy_prev(i) = bnd%dsxy_prev(i) + ds(2)
            bnd%dsyy_prev(i) = bnd%dsyy_prev(i) + ds(3)
         else
            if (last > 0) bnd%end_next(i) = last
            bnd%dsxx_next(i) = bnd%dsxx_next(i) + ds(1)
            bnd%dsxy_next(i) = bnd%dsxy_next(i) + ds(2)
            bnd%dsyy_next(i) = bnd%dsyy_next(i) + ds(3)
         end if
      end subroutine add_side_stress

      !> Dead force of stress st on half the segment (ex, ey) from point i's
      !> corner: L n = (-ey, ex) for a segment leaving it clockwise (sgn 1),
      !> (ey, -ex) for one arriving (sgn -1).
      subroutine add_segment(st, ex, ey, sgn)
         real(wp), intent(in) :: st(3), ex, ey, sgn
         real(wp) :: lnx, lny
         lnx = -0.5_wp*sgn*ey
         lny = 0.5_wp*sgn*ex
         bnd%dfx(i) = bnd%dfx(i) + st(1)*lnx + st(2)*lny
         bnd%dfy(i) = bnd%dfy(i) + st(2)*lnx + st(3)*lny
      end subroutine add_segment

      !> Condition `code` in direction d (1 x, 2 y) of point i: any prescribed
      !> velocity there (value and the gridpoint's vfix bit) is removed.
      subroutine set_code(i, g, d, code)
         integer(ip), intent(in) :: i, g
         integer, intent(in) :: d, code
         integer :: bit
         if (d == 1) then
            bnd%ix(i) = code
            bnd%vx(i) = 0.0_wp
            bit = vfix_x
         else
            bnd%iy(i) = code
            bnd%vy(i) = 0.0_wp
            bit = vfix_y
         end if
         if (g > 0) ctx%model%geometry%gridpoints%vfix(g) = &
            iand(ctx%model%geometry%gridpoints%vfix(g), not(bit))
      end subroutine set_code

      !> XFREE / YFREE in direction d (docs/zones.md "Loads under a prescribed
      !> velocity"): a prescribed velocity there is removed and the load stored
      !> under it acts again (code 1, or 0 when there is none); where no
      !> velocity holds, the load (total and increment) and the viscous
      !> dashpot of that direction are removed (code 0).
      subroutine free_direction(i, g, d)
         integer(ip), intent(in) :: i, g
         integer, intent(in) :: d
         ! a direction cannot be freed from a traction: the point's SET FUP
         ! tractions become fixed forces first (docs/zones.md)
         call boundary_freeze_point(bnd, ctx%model%geometry, i)
         if (d == 1) then
            call free_one(i, g, d, bnd%ix(i), bnd%fx(i), bnd%dfx(i), vis_x)
         else
            call free_one(i, g, d, bnd%iy(i), bnd%fy(i), bnd%dfy(i), vis_y)
         end if
      end subroutine free_direction

      !> free_direction in direction d, whose code (a copy), load, load
      !> increment and dashpot bit are given.
      subroutine free_one(i, g, d, code, f, df, bit)
         integer(ip), intent(in) :: i, g
         integer, intent(in) :: d, bit
         integer, value :: code
         real(wp), intent(inout) :: f, df
         if (code == bc_velocity) then
            call set_code(i, g, d, merge(bc_stress, bc_free, f /= 0.0_wp .or. df /= 0.0_wp))
         else
            call set_code(i, g, d, bc_free)
            bnd%vis(i) = iand(bnd%vis(i), not(bit))
            f = 0.0_wp; df = 0.0_wp
         end if
      end subroutine free_one

      !> A force condition in direction d replaces a velocity there; a load
      !> stored under that velocity stays in the total (the new one adds to it).
      subroutine set_force_code(i, g, d)
         integer(ip), intent(in) :: i, g
         integer, intent(in) :: d
         call set_code(i, g, d, bc_stress)
      end subroutine set_force_code

      !> A viscous condition in direction d replaces a prescribed velocity
      !> there, and the support's reaction at that moment becomes the point's
      !> total applied force in d: the dashpots then act on the dynamic motion
      !> only and the model stays in the equilibrium it reached (a seismic
      !> stage after a static one held by XVEL / YVEL 0, as Application A:
      !> without it the top and bottom of that model lose about 4 MPa of
      !> vertical load at the switch and the whole model springs open at
      !> 0.2 m/s before the wave arrives). Reaction: minus the unbalanced
      !> zone, contact and gravity force of the gridpoint, as PRINT BOUNDARY
      !> FORCES reports it. The gridpoint's force sum, which the first step of
      !> the next CYCLE moves it with (forces are summed at the end of a
      !> step), takes the new load at once, or that step would drop it.
      !> A load stored under the velocity (fx, not in the gridpoint's force
      !> sum) is part of that balance: the new total -(gp f + m g), which is
      !> the stored load plus the support's reaction, replaces it. The total
      !> acts times XMUL, so it is stored divided by a non-zero XMUL.
      !> Under SET FUP the point's stored load is partly its tractions (the
      !> stresses on its half edges, which boundary_step adds to the fixed
      !> force): the fixed part becomes the total minus the traction's
      !> present force, so the point keeps the total and its tractions still
      !> follow the boundary (before this, Application A's top and bottom
      !> carried their LSTRESS twice after the switch and moved at 1 m/s
      !> with no wave applied).
      subroutine velocity_to_viscous(i, g, d)
         integer(ip), intent(in) :: i, g
         integer, intent(in) :: d
         real(wp) :: tfx, tfy, tdfx, tdfy
         call boundary_traction_force(bnd, ctx%model%geometry, i, tfx, tfy, tdfx, tdfy)
         associate (gp => ctx%model%geometry%gridpoints)
            if (d == 1) then
               if (bnd%ix(i) /= bc_velocity) return
               if (g > 0) call take_reaction(gp%fx(g), gp%mass(g)*ctx%model%gravity(1), bnd%fx(i), &
                                             bnd%xmul(i), tfx)
            else
               if (bnd%iy(i) /= bc_velocity) return
               if (g > 0) call take_reaction(gp%fy(g), gp%mass(g)*ctx%model%gravity(2), bnd%fy(i), &
                                             bnd%ymul(i), tfy)
            end if
         end associate
         call set_code(i, g, d, bc_free)
      end subroutine velocity_to_viscous

      !> velocity_to_viscous in one direction: the gridpoint's force sum gf and
      !> weight mg, the point's stored load bf, its multiplier and traction
      !> force tf.
      subroutine take_reaction(gf, mg, bf, mul, tf)
         real(wp), intent(inout) :: gf, bf
         real(wp), intent(in) :: mg, mul, tf
         real(wp) :: f
         f = -(gf + mg)
         bf = f - tf
         if (mul /= 0.0_wp) bf = f/mul - tf
         gf = gf + f
      end subroutine take_reaction

      !> History type of the history keyword at item kk (and the type after it).
      subroutine history_of(kk, htype, freq, tload)
         integer, intent(in) :: kk
         integer, intent(out) :: htype
         real(wp), intent(out) :: freq, tload
         integer :: nt
         htype = bh_constant
         freq = 0.0_wp
         tload = 0.0_wp
         if (parsed%items(kk)%count > 0) then
            nt = parsed%int_at(kk, 1)
            if (nt > 2) then
               call set_error(error, 'BOUNDARY '//parsed%items(kk)%name// &
                              ': a history number must be 1 or 2 (read by HREAD)')
               return
            end if
            htype = bh_table1 + nt - 1
            return
         end if
         if (kk == parsed%nitems) return
         if (.not. any(type_words == parsed%items(kk + 1)%name)) return
         select case (parsed%items(kk + 1)%name)
         case ('LINEAR')
            htype = bh_linear
         case ('SINE', 'COSINE')
            htype = merge(bh_sine, bh_cosine, parsed%items(kk + 1)%name == 'SINE')
            freq = parsed%real_at(kk + 1, 1)
            tload = parsed%real_at(kk + 1, 2)
            if (freq < 0.0_wp .or. tload < 0.0_wp) then
               call set_error(error, 'BOUNDARY '//parsed%items(kk + 1)%name// &
                              ': expected freq >= 0 and tload >= 0')
               return
            end if
         case ('FUNCTION')
            call set_error(error, 'BOUNDARY FUNCTION: a user-supplied FHIST(T) needs the ' &
                           //'source code; read the history with HREAD n file and give ' &
                           //'XHISTORY n instead')
            return
         end select
      end subroutine history_of
   end subroutine do_boundary

   !> HREAD file (manual 4.5): line 1 a heading, line 2 `np tdel`, then np
   !> values (free format, any number per line), the first at time 0.
   subroutine boundary_read_table(file, table, error)
      character(len=*), intent(in) :: file
      type(boundary_table_t), intent(out) :: table
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, np
      real(wp) :: dt
      character(len=256) :: heading
      character(len=200) :: text
      open (newunit=u, file=file, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         call set_error(error, "cannot open file '"//file//"'")
         return
      end if
      read (u, '(a)', iostat=ios) heading
      if (ios /= 0) then
         call fail('it is empty (expected a heading line, then np tdel, then np values)')
         return
      end if
      read (u, *, iostat=ios) np, dt
      if (ios /= 0) then
         call fail('line 2 should hold np (number of values, an integer) and tdel ' &
                   //'(time step, a real)')
         return
      end if
      if (np < 1 .or. dt <= 0.0_wp) then
         call fail('line 2 should hold np >= 1 and tdel > 0')
         return
      end if
      allocate (table%values(np))
      read (u, *, iostat=ios) table%values
      if (ios /= 0) then
         write (text, '(a,i0,a)') 'expected ', np, ' numeric values after line 2'
         call fail(trim(text))
         return
      end if
      close (u)
      table%heading = trim(heading)
      table%np = np
      table%dt = dt
   contains
      subroutine fail(why)
         character(len=*), intent(in) :: why
         close (u)
         call set_error(error, "file '"//file//"': "//why)
         if (allocated(table%values)) deallocate (table%values)
      end subroutine fail
   end subroutine boundary_read_table

   ! ---- FFIELD --------------------------------------------------------------------

   !> FFIELD (manual Section 4.5; Section 3.8.2): GEN yl yu np; <y1 y2> MAT n /
   !> CONS n; ON; OFF; INITIALIZE (INT, as Application D prints it); and the
   !> base conditions XVEL v, YVEL v, SXY s, SXX s, XVISC, YVISC. The line is
   !> checked whole before the column changes (model_ffield, zones_ffield;
   !> docs/zones.md "Free field").
   subroutine do_ffield(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(ffield_t) :: ff
      integer :: k, kg, kl, d, nloose
      integer(ip) :: z, np, nset
      real(wp) :: y1, y2, yc, rho, m1, f
      logical :: ranged
      character(len=:), allocatable :: name
      character(len=200) :: text

      associate (model => ctx%model, out => ctx%out)
         kg = parsed%find('GEN')
         kl = 0
         nloose = 0
         do k = 1, parsed%nitems
            if (parsed%items(k)%keyword == item_loose) then
               kl = k
               nloose = parsed%items(k)%count
            end if
         end do
         if (parsed%nitems == 0 .or. (nloose > 0 .and. parsed%nitems == 1)) then
            call set_error(error, 'FFIELD: expected GEN yl yu np, MAT n, CONS n, ON, OFF, ' // &
                           'INITIALIZE or a base condition (XVEL, YVEL, SXX, SXY, XVISC, YVISC)')
            return
         end if
         if (nloose /= 0 .and. nloose /= 2) then
            call set_error(error, 'FFIELD: a range of the column is two y-coordinates y1 y2 ' // &
                           '(before MAT n / CONS n)')
            return
         end if
         ff = model%ffield
         if (kg > 0) then
            y1 = parsed%real_at(kg, 1)
            y2 = parsed%real_at(kg, 2)
            np = parsed%int_at(kg, 3)
            if (.not. (y2 > y1) .or. np < 2) then
               call set_error(error, 'FFIELD GEN yl yu np: expected yu > yl and at least 2 ' // &
                              'gridpoints np')
               return
            end if
            call ffield_generate(ff, y1, y2, np)
         else if (ff%np < 2) then
            call set_error(error, 'FFIELD: there is no free field yet: give FFIELD GEN yl yu ' // &
                                  'np first')
            return
         end if
         ranged = nloose == 2
         if (ranged) then
            y1 = parsed%real_at(kl, 1)
            y2 = parsed%real_at(kl, 2)
            ! lower limit first, as every range (commands_parser)
            if (y1 > y2) then
               call set_error(error, 'FFIELD y1 y2: expected y1 <= y2, got '// &
                              trim(format_real(y1))//' '//trim(format_real(y2)))
               return
            end if
            if (parsed%find('MAT') == 0 .and. parsed%find('CONS') == 0) then
               call set_error(error, 'FFIELD y1 y2: the range selects zones for MAT n / CONS ' // &
                                     'n; ' // &
                              'neither follows it')
               return
            end if
         end if
         k = parsed%find('CONS')
         if (k > 0) then
            if (.not. any(known_cons == parsed%int_at(k, 1))) then
               write (text, '(a,i0,a)') 'FFIELD CONS: unknown constitutive number ', &
                  parsed%int_at(k, 1), ' for free-field zones; known: 0, 1, 3'
               call set_error(error, trim(text))
               return
            end if
         end if
         k = parsed%find('MAT')
         if (k > 0) then
            if (parsed%int_at(k, 1) < 1) then
               call set_error(error, 'FFIELD MAT: expected a material number n >= 1')
               return
            end if
         end if

         ! from here on nothing fails: apply in order
         nset = 0
         do k = 1, parsed%nitems
            name = parsed%items(k)%name
            select case (name)
            case ('MAT', 'CONS')
               do z = 1, ff%np - 1
                  yc = ff%yl + (real(z, wp) - 0.5_wp)*ff%dy
                  if (ranged) then
                     if (yc < y1 .or. yc > y2) cycle
                  end if
                  if (name == 'MAT') ff%mat(z) = parsed%int_at(k, 1)
                  if (name == 'CONS') ff%cons(z) = parsed%int_at(k, 1)
                  nset = nset + 1
               end do
            case ('ON')
               ff%on = .true.
            case ('OFF')
               ff%on = .false.
            case ('INITIALIZE', 'INT')
               ff%sxx0 = ff%zn%sxx(1:ff%np - 1)
               ff%sxy0 = ff%zn%sxy(1:ff%np - 1)
            case ('XVEL', 'YVEL', 'SXY', 'SXX')
               ! a velocity (XVEL, YVEL), or SXY the shear and SXX the normal
               ! stress on the base, times the last BOUNDARY history (manual:
               ! "Histories defined in the BOUNDARY command are also used here")
               d = merge(1, 2, name == 'XVEL' .or. name == 'SXY')
               if (name == 'XVEL' .or. name == 'YVEL') then
                  ff%base_code(d) = ff_velocity
                  ff%base_v(d) = parsed%real_at(k, 1)
                  ff%base_visc(d) = .false.
               else
                  ff%base_code(d) = ff_stress
                  ff%base_s(d) = parsed%real_at(k, 1)
               end if
               ff%base_h = model%bound%zp%h_next
               ff%base_freq = model%bound%zp%freq_next
               ff%base_tload = model%bound%zp%tload_next
            case ('XVISC', 'YVISC')
               d = merge(1, 2, name == 'XVISC')
               if (ff%base_code(d) == ff_velocity) then
                  ! the support's reaction becomes a stored base force, so the
                  ! column stays in the equilibrium it reached (as BOUNDARY
                  ! XVISC after XVEL does for the blocks)
                  rho = model%materials%get(ff%mat(1), prop_density)
                  ! its weight, buoyant below the water table (zones_ffield)
                  if (allocated(model%fluid)) then
                     if (model%fluid%eff .and. ff%yl + 0.5_wp*ff%dy < model%fluid%ywtab) &
                        rho = rho - model%fluid%rhow
                  end if
                  m1 = 0.5_wp*rho*ff%dy
                  if (d == 1) then
                     f = -(ff%fx(1) - ff%base_f(1) + m1*model%gravity(1))
                  else
                     f = -(ff%fy(1) - ff%base_f(2) + m1*model%gravity(2))
                  end if
                  ff%base_f(d) = f
                  ff%base_code(d) = ff_free
               end if
               ff%base_visc(d) = .true.
            end select
         end do
         model%ffield = ff
         do k = 1, parsed%nitems
            if (parsed%items(k)%name == 'SXY' .or. parsed%items(k)%name == 'SXX') &
               call note_ffield_base(model, out, parsed%items(k)%name, parsed%real_at(k, 1))
         end do
         if (kg > 0) then
            write (text, '(a,i0,a,i0,4a)') 'FFIELD: free field of ', ff%np, ' gridpoints (', &
               ff%np - 1, ' zones) from y = ', trim(adjustl(fmt_real(ff%yl, 12, 5))), ' to ', &
               trim(adjustl(fmt_real(ff%yu, 12, 5)))
            call out%line(trim(text))
         end if
         if (parsed%find('MAT') > 0 .or. parsed%find('CONS') > 0) then
            write (text, '(a,i0,a)') 'FFIELD: ', nset/max(1, count([parsed%find('MAT') > 0, &
                                                                 parsed%find('CONS') > 0])), &
               ' free-field zone(s) set'
            call out%line(trim(text))
         end if
      end associate
   end subroutine do_ffield

   !> FFIELD SXY s / SXX s is a stress (Section 4.5) on the column's base; the
   !> model's base carries its own BOUNDARY STRESS. A wave that is to pass the
   !> free-field sides as the interior needs the same input on both (a new
   !> user copied Application D's `FFIELD SXY=1` under `BOUND STRESS 0 2E5 0`:
   !> the sides, tied to a column driven by 1 Pa, held the site still, surface
   !> 0.0085 m/s for 0.063). Where the lowest boundary points carry a stress
   !> sxy (syy for SXX) other than s by more than 1 %, a note names both.
   subroutine note_ffield_base(model, out, name, s)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: s
      real(wp) :: ymin, y, base, v(2), tol
      integer(ip) :: i
      integer :: c
      associate (b => model%bound, cx => model%geometry%corners)
         if (b%n == 0 .or. .not. b%fup) return
         c = merge(2, 3, name == 'SXY')
         ymin = huge(1.0_wp)
         do i = 1, b%n
            ymin = min(ymin, cx%y(b%corner(i)))
         end do
         tol = 1.0e-6_wp*max(1.0_wp, abs(ymin))
         base = 0.0_wp
         do i = 1, b%n
            y = cx%y(b%corner(i))
            if (y > ymin + tol) cycle
            if (c == 2) then
               v = [b%sxy_prev(i) + b%dsxy_prev(i), b%sxy_next(i) + b%dsxy_next(i)]
            else
               v = [b%syy_prev(i) + b%dsyy_prev(i), b%syy_next(i) + b%dsyy_next(i)]
            end if
            if (abs(v(1)) > abs(base)) base = v(1)
            if (abs(v(2)) > abs(base)) base = v(2)
         end do
         if (base == 0.0_wp .or. abs(s - base) <= 0.01_wp*max(abs(s), abs(base))) return
         call out%line('note: FFIELD '//name//' '//trim(format_real(s))//' is a stress on the ' // &
                       'base of the free field (manual Section 4.5, FFIELD); the model''s ' // &
                       'base (y = '//trim(format_real(ymin))//') carries BOUNDARY STRESS '// &
                       trim(merge('sxy', 'syy', c == 2))//' '//trim(format_real(base))// &
                       ': a wave that is to pass the free-field sides as the interior wants ' // &
                       'the same input on both (FFIELD '//name//' '//trim(format_real(base))//')')
      end associate
   end subroutine note_ffield_base

   !> PRINT FF: the free-field column, gridpoints (y, velocities,
   !> displacements) and zones (material, model, stresses less the saved
   !> initial ones, plasticity state).
   subroutine ffield_print(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer(ip) :: i
      character(len=240) :: text
      associate (ff => model%ffield)
         if (ff%np < 2) then
            call out%line('PRINT FF: there is no free field (FFIELD GEN yl yu np)')
            return
         end if
         write (text, '(a,i0,3a)') 'FREE FIELD  (', ff%np, ' gridpoints, ', &
            trim(merge('on ', 'off', ff%on)), ')'
         call out%line(trim(text))
         call out%line('  GP             Y            XV            YV            XD            YD')
         do i = ff%np, 1, -1
            write (text, '(i4,5a)') i, fmt_real(ff%yl + real(i - 1, wp)*ff%dy), &
               fmt_real(ff%vx(i) + 0.0_wp), fmt_real(ff%vy(i) + 0.0_wp), &
               fmt_real(ff%ux(i) + 0.0_wp), fmt_real(ff%uy(i) + 0.0_wp)
            call out%line(trim(text))
         end do
         call out%line('ZONE MAT CON            YC           SXX           SXY           SYY' // &
                       '      SXX-SXX0      SXY-SXY0  STATE')
         do i = ff%np - 1, 1, -1
            write (text, '(i4,i4,i4,6a,i7)') i, ff%mat(i), ff%cons(i), &
               fmt_real(ff%yl + (real(i, wp) - 0.5_wp)*ff%dy), fmt_real(ff%zn%sxx(i) + 0.0_wp), &
               fmt_real(ff%zn%sxy(i) + 0.0_wp), fmt_real(ff%zn%syy(i) + 0.0_wp), &
               fmt_real(ff%zn%sxx(i) - ff%sxx0(i) + 0.0_wp), &
               fmt_real(ff%zn%sxy(i) - ff%sxy0(i) + 0.0_wp), ff%zn%state(i)
            call out%line(trim(text))
         end do
         write (text, '(a,2(a,i0),4a)') 'Base:', ' x code ', ff%base_code(1), ', y code ', &
            ff%base_code(2), ' (0 free, 1 stress, 4 velocity); viscous x ', &
            trim(merge('yes', 'no ', ff%base_visc(1))), ', y ', trim(merge('yes', 'no ', ff%base_visc(2)))
         call out%line(trim(text))
      end associate
   end subroutine ffield_print

   ! ---- INSITU --------------------------------------------------------------------

   !> INSITU on simply-deformable blocks: the strain modes are loaded by the
   !> first moment of the block's contact forces about its centroid
   !> (engine_sdef), and a contact's force acts at its corner, not at the
   !> centre of the stretch of joint it stands for (cx, cy), and carries the
   !> couples that balance the rigid moments (v, against the traction's v0).
   !> Over the whole outline the field's first moment is A sigma; the
   !> stretches' part differs by sum (x_c - x_b) (x) v - (c - x_b) (x) v0,
   !> which the block's uniform stress takes (symmetric part, over A), so its
   !> strain modes start balanced. Before: 2.7e4 N out of balance in a
   !> jointed SDEF tunnel at rest (T-junctions), 1.3e-3 m/s at cycle 1000;
   !> its rigid twin was still to 1e-12.
   subroutine sdef_insitu_moments(geo, range, inr, cx, cy, v0x, v0y, vx, vy)
      type(geometry_t), intent(inout) :: geo
      type(range_t), intent(in) :: range
      logical, intent(in) :: inr(:)
      real(wp), intent(in) :: cx(:), cy(:), v0x(:), v0y(:), vx(:), vy(:)
      real(wp), allocatable :: q(:, :)
      integer(ip) :: c, b, k
      real(wp) :: sg
      allocate (q(3, geo%blocks%n), source=0.0_wp)
      do c = 1, geo%contacts%n
         if (.not. inr(c)) cycle
         do k = 1, 2
            b = merge(geo%contacts%block1(c), geo%contacts%block2(c), k == 1)
            if (.not. insitu_sdef(b)) cycle
            ! the force on block1 is v, on block2 -v
            sg = merge(1.0_wp, -1.0_wp, k == 1)
            call add(b, geo%contacts%x(c), geo%contacts%y(c), sg*vx(c), sg*vy(c))
            call add(b, cx(c), cy(c), -sg*v0x(c), -sg*v0y(c))
         end do
      end do
      do b = 1, geo%blocks%n
         if (.not. insitu_sdef(b)) cycle
         geo%blocks%sxx(b) = geo%blocks%sxx(b) + q(1, b)/geo%blocks%area(b)
         geo%blocks%syy(b) = geo%blocks%syy(b) + q(2, b)/geo%blocks%area(b)
         geo%blocks%sxy(b) = geo%blocks%sxy(b) + q(3, b)/geo%blocks%area(b)
      end do
   contains
      logical function insitu_sdef(blk)
         integer(ip), intent(in) :: blk
         insitu_sdef = geo%blocks%live(blk) .and. geo%blocks%sdef(blk)
         if (insitu_sdef) insitu_sdef = geo%blocks%nzone(blk) == 0
         if (insitu_sdef) insitu_sdef = geo%blocks%area(blk) > 0.0_wp .and. &
                                        range%contains_point(geo%blocks%xc(blk), geo%blocks%yc(blk))
      end function insitu_sdef
      subroutine add(blk, px, py, fx, fy)
         integer(ip), intent(in) :: blk
         real(wp), intent(in) :: px, py, fx, fy
         real(wp) :: ox, oy
         ox = px - geo%blocks%xc(blk)
         oy = py - geo%blocks%yc(blk)
         q(1, blk) = q(1, blk) + fx*ox
         q(2, blk) = q(2, blk) + fy*oy
         q(3, blk) = q(3, blk) + 0.5_wp*(fx*oy + fy*ox)
      end subroutine add
   end subroutine sdef_insitu_moments

   !> INSITU <range> <STRESS sxx sxy syy> <XGRAD sxxx sxyx syyx> <YGRAD ...> <NODIS>
   !> (docs/zones.md "Initial stresses").
   subroutine do_insitu(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: ks, kx, ky, n, m
      integer(ip) :: z, c, b, nz, nc, nsd
      real(wp) :: s0(3), gx(3), gy(3), s(3), x, y, kb, gs, nx, ny, tx, ty
      real(wp) :: l, fn, fs, scale, kn, ks_eff, strength, ratio, worst
      integer(ip) :: nslip, ntens, cworst
      logical :: nodis, mixed, worst_pulled
      logical, allocatable :: no_elastic(:)
      real(wp), allocatable :: cx(:), cy(:), w(:), jnx(:), jny(:), vx(:), vy(:), dm(:)
      real(wp), allocatable :: v0x(:), v0y(:), pc(:)
      integer(ip), allocatable :: ends(:, :)
      logical, allocatable :: inr(:)
      real(wp) :: ds(3), dtx, dty
      type(joint_props_t) :: props
      character(len=200) :: text
      associate (model => ctx%model, out => ctx%out)
         ks = parsed%find('STRESS')
         kx = parsed%find('XGRAD')
         ky = parsed%find('YGRAD')
         nodis = parsed%find('NODIS') > 0
         if (ks == 0 .and. kx == 0 .and. ky == 0) then
            call set_error(error, 'INSITU: expected STRESS sxx sxy syy (and / or XGRAD, YGRAD)')
            return
         end if
         if (geometry_live_blocks(model%geometry) == 0) then
            call set_error(error, 'INSITU: there are no blocks (give BLOCK first)')
            return
         end if
         s0 = 0.0_wp; gx = 0.0_wp; gy = 0.0_wp
         if (ks > 0) s0 = [(parsed%real_at(ks, n), n = 1, 3)]
         if (kx > 0) gx = [(parsed%real_at(kx, n), n = 1, 3)]
         if (ky > 0) then
            if (parsed%items(ky)%count == 3) then
               gy = [(parsed%real_at(ky, n), n = 1, 3)]
            else
               ! the manual's two-value form YGRAD sxyy syyy (docs/zones.md)
               gy = [0.0_wp, parsed%real_at(ky, 1), parsed%real_at(ky, 2)]
            end if
         end if

         associate (geo => model%geometry, mats => model%materials)
            ! zones: stress at the zone centroid; szz of plane strain from K and G
            m = 1
            do b = 1, geo%blocks%n
               if (geo%blocks%live(b)) m = max(m, int(geo%blocks%material(b)))
            end do
            allocate (no_elastic(m))
            no_elastic = .false.
            nz = 0
            do z = 1, geo%zones%n
               if (.not. geo%zones%live(z)) cycle
               b = geo%zones%block(z)
               if (.not. geo%blocks%live(b)) cycle
               x = (geo%gridpoints%x(geo%zones%g1(z)) + geo%gridpoints%x(geo%zones%g2(z)) &
                    + geo%gridpoints%x(geo%zones%g3(z)))/3.0_wp
               y = (geo%gridpoints%y(geo%zones%g1(z)) + geo%gridpoints%y(geo%zones%g2(z)) &
                    + geo%gridpoints%y(geo%zones%g3(z)))/3.0_wp
               if (.not. parsed%range%contains_point(x, y)) cycle
               s = stress_at(s0, gx, gy, x, y)
               m = geo%blocks%material(b)
               kb = mats%get(m, prop_bulk)
               gs = mats%get(m, prop_shear)
               if (.not. kb > 0.0_wp .and. m >= 1) no_elastic(m) = .true.
               call set_zone_stress(geo%zones, z, s, kb, gs)
               nz = nz + 1
            end do
            ! simply-deformable blocks: their uniform stress, the field at the
            ! centroid (its mean over the block for a linear field)
            nsd = 0
            if (allocated(geo%blocks%sdef)) then
               do b = 1, geo%blocks%n
                  if (.not. geo%blocks%live(b)) cycle
                  if (.not. geo%blocks%sdef(b) .or. geo%blocks%nzone(b) > 0) cycle
                  if (.not. parsed%range%contains_point(geo%blocks%xc(b), geo%blocks%yc(b))) cycle
                  s = stress_at(s0, gx, gy, geo%blocks%xc(b), geo%blocks%yc(b))
                  geo%blocks%sxx(b) = s(1)
                  geo%blocks%sxy(b) = s(2)
                  geo%blocks%syy(b) = s(3)
                  nsd = nsd + 1
               end do
            end if

            ! joints: forces from the traction on the contact, compression
            ! positive: the resultant over the stretch of joint the contact
            ! stands for (its length), exact for a linear field when the
            ! stress is taken at the stretch's centre (a quarter spacing
            ! inside the end of a joint; contact_joint_chains). The traction
            ! is that on the joint (the chord of the contacts' chain), put
            ! into each contact's frame as the first CYCLE step has it
            ! (contact_settle_geometry): a contact between two rounded
            ! corners leans off the joint, and the traction on its own normal
            ! left a rigid block out of balance (random tunnels: 2.4e-3 m/s
            ! before any excavation).
            call geometry_refresh(geo)
            call contact_settle_geometry(geo, contact_margin(geo))
            call contact_joint_chains(geo, contact_margin(geo), cx, cy, w, jnx, jny, ends)
            allocate (vx(geo%contacts%n), vy(geo%contacts%n), dm(geo%contacts%n))
            vx = 0.0_wp
            vy = 0.0_wp
            dm = 0.0_wp
            do c = 1, geo%contacts%n
               if (.not. geo%contacts%live(c)) cycle
               if (.not. parsed%range%contains_point(geo%contacts%x(c), geo%contacts%y(c))) cycle
               if (ends(1, c) == 0 .and. (geo%blocks%fdef(geo%contacts%block1(c)) .or. &
                                          geo%blocks%fdef(geo%contacts%block2(c)))) then
                  ! a zoned block's gridpoint takes from its zones the
                  ! traction weighted by its hat function over the edges on
                  ! either side (to the neighbouring contacts, a and b away),
                  ! w t(0) + (b**2 - a**2)/6 dt/ds for a linear traction; the
                  ! stretch's centre, (b - a)/4 from the vertex, gives
                  ! (b**2 - a**2)/8 dt/ds. The hat's value is the traction
                  ! at 4/3 of the way to the stretch's centre. (Zoned, joints
                  ! at 45 and 90 degrees, gravity: 1.6e3 N out of balance at
                  ! cycle 1 where the gridpoint spacing changes from 1 to 2
                  ! m, the difference w (b - a)/4 (1/3) dt/ds.)
                  call corner_anchor(geo, c, x, y)
                  s = stress_at(s0, gx, gy, x + 4.0_wp/3.0_wp*(cx(c) - x), &
                                y + 4.0_wp/3.0_wp*(cy(c) - y))
               else
                  s = stress_at(s0, gx, gy, cx(c), cy(c))
               end if
               ! the force on block1 (sigma . n over the stretch, n the joint
               ! normal from block1 to block2)
               vx(c) = (s(1)*jnx(c) + s(2)*jny(c))*w(c)
               vy(c) = (s(2)*jnx(c) + s(3)*jny(c))*w(c)
               ! it acts at the contact point, the traction at the stretch's
               ! centre: the moment between them, per chain (kept at its
               ! first end contact)
               if (ends(1, c) > 0) then
                  ! plus, for a varying stress, the traction's moment about the
                  ! stretch's centre: (u x dt/ds) w**3 / 12 (u along the chord)
                  ds = (gx*jny(c) - gy*jnx(c))
                  dtx = ds(1)*jnx(c) + ds(2)*jny(c)
                  dty = ds(2)*jnx(c) + ds(3)*jny(c)
                  dm(ends(1, c)) = dm(ends(1, c)) + (cx(c) - geo%contacts%x(c))*vy(c) &
                                   - (cy(c) - geo%contacts%y(c))*vx(c) &
                                   + (jny(c)*dty + jnx(c)*dtx)*w(c)**3/12.0_wp
               end if
            end do
            ! each block pair: a couple gives its chains' stretches their
            ! moment back (the end contact points lie a rounding length
            ! inside the joint's ends, and the end stretches differ); it is
            ! put on the pair's two contacts farthest apart (pair_couples)
            allocate (inr(geo%contacts%n))
            do c = 1, geo%contacts%n
               inr(c) = geo%contacts%live(c)
               if (inr(c)) inr(c) = parsed%range%contains_point(geo%contacts%x(c), geo%contacts%y(c))
            end do
            v0x = vx
            v0y = vy
            call pair_couples(geo, ends, dm, inr, vx, vy)
            call zoned_contact_balance(geo, mats, model%gravity, inr, w, vx, vy)
            if (nsd > 0) call sdef_insitu_moments(geo, parsed%range, inr, cx, cy, v0x, v0y, &
                                                  vx, vy)
            nc = 0
            nslip = 0
            ntens = 0
            cworst = 0
            worst = 0.0_wp
            worst_pulled = .false.
            call insitu_pore_pressures(model, parsed%range, out, pc, error)
            if (allocated(error)) return
            do c = 1, geo%contacts%n
               if (.not. geo%contacts%live(c)) cycle
               if (.not. parsed%range%contains_point(geo%contacts%x(c), geo%contacts%y(c))) cycle
               nx = geo%contacts%nx(c)
               ny = geo%contacts%ny(c)
               tx = -ny
               ty = nx
               l = geo%contacts%length(c)
               fn = -(nx*vx(c) + ny*vy(c)) + 0.0_wp     ! + 0: no -0 in the tables
               ! SET -EFF: the joint carries the effective normal force
               if (allocated(pc)) fn = fn - pc(c)*l
               fs = (tx*vx(c) + ty*vy(c)) + 0.0_wp
               geo%contacts%state%fn(c) = fn
               geo%contacts%state%fs(c) = fs
               props = joint_props_of(mats, int(geo%contacts%jmat(c)), int(geo%contacts%jcons(c)))
               scale = 1.0_wp
               if (geo%contacts%jcons(c) /= 1) scale = l
               kn = props%kn*scale
               ks_eff = props%ks*scale
               if (geo%contacts%jcons(c) == 3 .and. l > 0.0_wp) then
                  ! stiffness of the continuously-yielding law at this normal stress
                  if (props%en /= 0.0_wp .and. fn > 0.0_wp) kn = kn*(fn/l)**props%en
                  if (props%es /= 0.0_wp .and. fn > 0.0_wp) ks_eff = ks_eff*(fn/l)**props%es
               end if
               if (.not. nodis .and. kn > 0.0_wp) then
                  geo%contacts%state%un(c) = -fn/kn
                  ! a joint closed by the field opens when its gap has grown
                  ! by fn / kn, and carries force again once it is back
                  ! there: that zero-force gap is what ud holds (the
                  ! opening the contact's open test and the reclosing
                  ! allow, contact_mechanics). Before, a preloaded joint
                  ! that opened took no force until its geometric gap
                  ! closed: a block that jumped off its INSITU-loaded
                  ! joint came to rest fn / kn lower (camp10, finding D).
                  if (fn > 0.0_wp) then
                     call joint_state_ud(geo%contacts)
                     geo%contacts%state%ud(c) = max(geo%contacts%gap(c) + fn/kn, 0.0_wp)
                  end if
               end if
               if (ks_eff > 0.0_wp) geo%contacts%state%us(c) = fs/ks_eff
               nc = nc + 1
               ! Coulomb strength of the joint (JCONS 1, 2, 5; Section 3.3):
               ! a field the joints cannot hold slips at the first cycle
               ! a tensile field (stresses positive in tension, manual Section
               ! 4.1): a joint pulled beyond its tensile strength opens at once
               if (props%kn > 0.0_wp .and. fn < 0.0_wp .and. -fn > 1.001_wp*props%tension*scale) &
                  ntens = ntens + 1
               if (props%kn > 0.0_wp .and. geo%contacts%jcons(c) /= 3) then
                  strength = props%friction*max(fn, 0.0_wp) + props%cohesion*scale
                  if (abs(fs) > 1.0e-6_wp*abs(fn) + 1.001_wp*strength) then
                     nslip = nslip + 1
                     ! a joint with no strength slips under any shear: the
                     ! worst of all; no friction and no cohesion, or friction
                     ! but a field pulling the joint apart (no normal force)
                     ratio = huge(1.0_wp)
                     if (strength > 0.0_wp) then
                        if (abs(fs)*1.0e-300_wp < strength) ratio = abs(fs)/strength
                     end if
                     if (ratio > worst) then
                        worst = ratio
                        cworst = c
                        worst_pulled = strength <= 0.0_wp .and. props%friction > 0.0_wp
                     end if
                  end if
               end if
            end do
            ! contacts now carry forces: later geometry changes update them in place
            ! instead of rebuilding them force-free (contact_refresh)
            if (nc > 0) geo%mechanical = .true.
         end associate
         write (text, '(a,i0,a,i0,a)') 'INSITU: stresses set in ', nz, ' zone(s) and ', nc, &
            ' contact(s)'
         if (nsd > 0) write (text, '(a,i0,a,i0,a,i0,a)') 'INSITU: stresses set in ', nz, &
            ' zone(s), ', nsd, ' SDEF block(s) and ', nc, ' contact(s)'
         call out%line(trim(text))
         if (nslip > 0) then
            associate (cts => model%geometry%contacts)
               call out%line('Note: INSITU: '//itoa(nslip)//' of '//itoa(nc)// &
                             ' contact(s) carry more shear than their joint strength allows '// &
                             '(friction x normal force + cohesion; worst: contact '// &
                             itoa(cworst)//' at ('//trim(adjustl(fmt_real(cts%x(cworst), 12, 5)))// &
                             ', '//trim(adjustl(fmt_real(cts%y(cworst), 12, 5)))//'), '// &
                             trim(worst_text())//'): '// &
                             'they slip at the first cycle (joints too weak for this field, '// &
                             'or a strip of joint shorter than the rounding at a junction)')
            end associate
         end if
         if (ntens > 0) call out%line('Note: INSITU: '//itoa(ntens)//' of '//itoa(nc)// &
                                      ' contact(s) are pulled apart beyond their joint''s '// &
                                      'tensile strength and open at the first cycle: stresses '// &
                                      'are positive in tension (manual Section 4.1); a rock '// &
                                      'mass under load wants negative (compressive) stresses')
         ! the free-field column (FFIELD GEN): its zones whose centre height is
         ! in the range's y-interval (any y for a range that is not a box); the
         ! column has no x, so the stress is taken at x = 0 (docs/zones.md)
         if (model%ffield%np > 1) then
            nz = 0
            associate (ff => model%ffield)
               kb = model%materials%get(ff%mat(1), prop_bulk)
               do z = 1, ff%np - 1
                  y = ff%yl + (real(z, wp) - 0.5_wp)*ff%dy
                  if (parsed%has_range .and. parsed%range%kind == range_box) then
                     if (y < parsed%range%yl .or. y > parsed%range%yu) cycle
                  end if
                  s = stress_at(s0, gx, gy, 0.0_wp, y)
                  kb = model%materials%get(ff%mat(z), prop_bulk)
                  gs = model%materials%get(ff%mat(z), prop_shear)
                  call set_zone_stress(ff%zn, z, s, kb, gs)
                  nz = nz + 1
               end do
            end associate
            write (text, '(a,i0,a)') 'INSITU: and in ', nz, ' free-field zone(s)'
            call out%line(trim(text))
         end if
         ! unzoned blocks: with no joint loaded, a later GENERATE may still
         ! zone them, and its zones will not have these stresses; beside
         ! zoned blocks, with the joints loaded, GENERATE is refused and they
         ! stay rigid. Say which; a model of rigid blocks only whose joints
         ! now carry the field (as the user made it) gets nothing.
         nz = 0
         mixed = any(model%geometry%blocks%nzone(1:model%geometry%blocks%n) > 0 .and. &
                     model%geometry%blocks%live(1:model%geometry%blocks%n))
         if (nc == 0 .or. mixed) then
         do b = 1, model%geometry%blocks%n
            if (.not. model%geometry%blocks%live(b)) cycle
            if (model%geometry%blocks%nzone(b) > 0) cycle
            ! an SDEF block took the stress above (its uniform stress)
            if (model%geometry%blocks%sdef(b)) cycle
            if (.not. parsed%range%contains_point(model%geometry%blocks%xc(b), &
                                                  model%geometry%blocks%yc(b))) cycle
            nz = nz + 1
         end do
         end if
         if (nz > 0 .and. nc == 0) then
            call out%line('Note: '//itoa(nz)//' block(s) in the range are rigid (not zoned): '// &
               'zones a later GENERATE makes will not have these stresses (to zone them, give '// &
               'GENERATE before INSITU)')
         else if (nz > 0) then
            call out%line('Note: '//itoa(nz)//' block(s) in the range are rigid (not zoned) '// &
               'beside zoned ones: their contacts have these stresses, and they stay rigid '// &
               '(GENERATE zones no block once INSITU has loaded the joints: give it before INSITU)')
         end if
         do m = 1, size(no_elastic)
            if (.not. no_elastic(m)) cycle
            write (text, '(a,i0,a)') 'Note: material ', m, ' has no BULK (K) yet; szz stays 0 ' &
               //'until PROPERTY gives its K and G (then szz = nu (sxx + syy))'
            call out%line(trim(text))
         end do
      end associate
   contains
      !> the worst contact's shear against its strength, for the note
      function worst_text() result(t)
         character(len=:), allocatable :: t
         if (worst >= huge(1.0_wp) .and. worst_pulled) then
            ! camp11: a joint with JFRIC > 0 under a tensile field was
            ! said to have no friction
            t = 'a joint in tension: no normal force for its friction to act on, no cohesion'
         else if (worst >= huge(1.0_wp)) then
            t = 'a joint with no strength (no friction, no cohesion)'
         else
            t = trim(adjustl(fmt_real(worst, 10, 3)))//' times its strength'
         end if
      end function worst_text
   end subroutine do_insitu

   ! ---- PRINT BOUNDARY ------------------------------------------------------------

   !> PRINT <range> BOUNDARY <STATE> <DISP> <FORCES> (all three without a
   !> sub-keyword); `subs` holds the sub-keywords given. Layout: docs/print.md.
   subroutine boundary_print(model, subs, out, range)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: subs(:)
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer :: j
      ! the fluid conditions of the boundary joints are not corner records
      if (any(subs == 'FLUID')) call print_boundary_fluid(model, out, range)
      if (size(subs) > 0 .and. all(subs == 'FLUID')) return
      if (model%bound%n == 0) then
         call out%line('  no boundary conditions (no BOUNDARY command has been applied)')
         if (size(subs) == 0 .or. any(subs == 'STATE')) call print_zpress(model, out, range)
         return
      end if
      if (size(subs) == 0) then
         call boundary_table(model, 'STATE', out, range)
         call boundary_table(model, 'FORCES', out, range)
         call boundary_table(model, 'DISPLACEMENTS', out, range)
         return
      end if
      do j = 1, size(subs)
         select case (subs(j))
         case ('STATE', 'FORCES', 'DISPLACEMENTS')
            call boundary_table(model, trim(subs(j)), out, range)
         case ('FLUID')
         case default
            call out%line('*** PRINT BOUNDARY '//trim(subs(j))//': not yet available ' &
                          //'(no boundary elements, fluid flow or thermal boundaries yet)')
         end select
      end do
   end subroutine boundary_print

   !> '(x, y)' of corner c, for the notes that name the first point concerned.
   function corner_text(geo, c) result(text)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      character(len=:), allocatable :: text
      text = '('//trim(adjustl(fmt_real(geo%corners%x(c), 12, 5)))//', '// &
             trim(adjustl(fmt_real(geo%corners%y(c), 12, 5)))//')'
   end function corner_text

   !> INSITU: zone z takes the in-plane stress s (sxx, sxy, syy) and the szz
   !> of plane strain, nu (sxx + syy), nu from its material's K and G (0
   !> without K).
   pure subroutine set_zone_stress(zn, z, s, kb, gs)
      type(zone_list_t), intent(inout) :: zn
      integer(ip), intent(in) :: z
      real(wp), intent(in) :: s(3), kb, gs
      real(wp) :: nu
      nu = 0.0_wp
      if (kb > 0.0_wp) nu = (3.0_wp*kb - 2.0_wp*gs)/(2.0_wp*(3.0_wp*kb + gs))
      zn%sxx(z) = s(1)
      zn%sxy(z) = s(2)
      zn%syy(z) = s(3)
      zn%szz(z) = nu*(s(1) + s(3))
   end subroutine set_zone_stress

   logical function shown(model, i, range) result(ok)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: i
      type(range_t), intent(in), optional :: range
      integer(ip) :: c
      c = model%bound%corner(i)
      ok = model%geometry%corners%live(c)
      if (.not. ok) return
      ok = model%geometry%blocks%live(model%geometry%corners%block(c))
      if (.not. ok .or. .not. present(range)) return
      ok = range%contains_point(model%geometry%corners%x(c), model%geometry%corners%y(c))
   end function shown

   !> Condition code PRINT BOUNDARY shows in one direction: 3 (viscous) when
   !> that direction has a dashpot, whether or not a stress acts there too.
   pure integer function shown_code(code, vis, bit)
      integer, intent(in) :: code, vis, bit
      shown_code = code
      if (iand(vis, bit) /= 0 .and. code /= bc_velocity) shown_code = bc_viscous
   end function shown_code

   !> Short name of a history type (PRINT BOUNDARY STATE HX HY, SET ZPRESS).
   pure function boundary_history_name(h) result(text)
      integer, intent(in) :: h
      character(len=4) :: text
      select case (h)
      case (bh_constant); text = 'CONS'
      case (bh_linear); text = 'LIN'
      case (bh_sine); text = 'SINE'
      case (bh_cosine); text = 'COS'
      case default
         write (text, '(a,i1)') 'H', h - bh_table1 + 1
      end select
   end function boundary_history_name

   !> The SET ZPRESS sources (after the STATE table); with a range, those
   !> whose centre lies in it.
   subroutine print_zpress(model, out, range)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: i
      character(len=140) :: text
      associate (zp => model%bound%zp)
         if (zp%n == 0) return
         call out%line('ZPRESS SOURCES  (pressure compression positive; HIST: history during ' &
                       //'the next CYCLE)')
         call out%line('  SOURCE             X             Y        RADIUS            PZ' // &
                       '   ZONES  HIST')
         do i = 1, zp%n
            if (present(range)) then
               if (.not. range%contains_point(zp%x(i), zp%y(i))) cycle
            end if
            write (text, '(i8,4a,i8,2x,a4)') i, fmt_real(zp%x(i)), fmt_real(zp%y(i)), &
               fmt_real(zp%rad(i)), fmt_real(zp%pz(i)), &
               zp%nzone(i), boundary_history_name(zp%h(i))
            call out%line(trim(text))
         end do
      end associate
   end subroutine print_zpress

   !> One table of PRINT BOUNDARY, `which` STATE, FORCES or DISPLACEMENTS:
   !> a row per boundary point shown (live, and in the range when given).
   subroutine boundary_table(model, which, out, range)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: which
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: i, c, g, nheld, j, blk, p
      real(wp) :: sx, sy
      character(len=200) :: text
      real(wp), allocatable :: rrx(:), rry(:), px(:), py(:)
      real(wp) :: fblk(3)
      type(rigid_velocity_t) :: rv
      nheld = 0
      sx = 0.0_wp; sy = 0.0_wp
      ! the reactions at velocity-held corners of rigid and SDEF blocks: the
      ! part of each held block's force its constraints hold, shared among
      ! its held corners (rigid_velocity_reactions)
      allocate (rrx(max(1_ip, model%bound%n)), rry(max(1_ip, model%bound%n)))
      rrx = 0.0_wp
      rry = 0.0_wp
      if (which == 'FORCES' .and. rigid_velocity_present(model%bound, model%geometry)) then
         call rigid_velocity_build(model%bound, model%geometry, rv)
         associate (bl => model%geometry%blocks)
            do j = 1, rv%nblk
               blk = rv%blk(j)
               if (.not. bl%live(blk) .or. bl%fixed(blk)) cycle
               allocate (px(rv%cnt(j)), py(rv%cnt(j)))
               fblk = [bl%fx(blk) + bl%mass(blk)*model%gravity(1) + bl%lx(blk), &
                       bl%fy(blk) + bl%mass(blk)*model%gravity(2) + bl%ly(blk), bl%fm(blk)]
               call rigid_velocity_reactions(rv, model%bound, model%geometry, j, blk, &
                                             bl%mass(blk), bl%inertia(blk), fblk, px, py)
               do p = 1, rv%cnt(j)
                  rrx(rv%pts(rv%first(j) + p - 1)) = px(p)
                  rry(rv%pts(rv%first(j) + p - 1)) = py(p)
               end do
               deallocate (px, py)
            end do
         end associate
      end if
      select case (which)
      case ('STATE')
         call out%line('BOUNDARY STATE  (codes: 0 free, 1 stress/load, 3 viscous, 4 velocity)')
         call out%line('  COR: corner id; ADDRESS: its 1989 address (the manual''s COR ' // &
                       'column); BOUNDARY CORNER takes either, an address first')
         call out%line('     COR   BLOCK      GP             X             Y  IX  IY' // &
                       '          XMUL          YMUL    HX   HY   MAT  ADDRESS')
      case ('FORCES')
         call out%line('BOUNDARY FORCES  (FX FY: applied total, or the reaction where the ' &
                       //'velocity is prescribed; DFX DFY: increment for the next CYCLE)')
         call out%line('     COR             X             Y  IX  IY            FX            FY' &
                       //'           DFX           DFY')
      case default
         call out%line('BOUNDARY DISPLACEMENTS  (VX VY: prescribed velocity where IX / IY = 4)')
         call out%line('     COR             X             Y            UX            UY' // &
                       '            VX            VY')
      end select
      associate (b => model%bound, co => model%geometry%corners, &
                 gp => model%geometry%gridpoints)
         do i = 1, b%n
            if (.not. shown(model, i, range)) cycle
            c = b%corner(i)
            g = co%gp(c)
            select case (which)
            case ('STATE')
               write (text, '(3i8,2a,2i4,2a,2(1x,a4),i6,i9)') c, co%block(c), co%gp(c), &
                  fmt_real(co%x(c)), fmt_real(co%y(c)), shown_code(b%ix(i), b%vis(i), vis_x), &
                  shown_code(b%iy(i), b%vis(i), vis_y), fmt_real(b%xmul(i)), fmt_real(b%ymul(i)), &
                  boundary_history_name(b%hx(i)), boundary_history_name(b%hy(i)), b%vmat(i), &
                  co%addr(c)
            case ('FORCES')
               call forces_row()
            case default
               call displacements_row()
            end select
            call out%line(trim(text))
         end do
      end associate
      if (which == 'STATE') call print_zpress(model, out, range)
      if (nheld > 0) then
         write (text, '(a,i0,5a)') '  Note: ', nheld, ' velocity direction(s) hold a stored ' &
            //'load (sum FX', fmt_real(sx + 0.0_wp), ', FY', fmt_real(sy + 0.0_wp), &
            '), included in the reactions above; it acts again after XFREE / YFREE'
         call out%line(trim(text))
      end if
   contains
      !> FORCES row of point i: the applied force, or the reaction where the
      !> velocity is prescribed (the stored loads of such points add to nheld,
      !> sx, sy).
      subroutine forces_row()
         real(wp) :: fx, fy, ax, ay, tfx, tfy, tdfx, tdfy
         associate (b => model%bound, co => model%geometry%corners, &
                    gp => model%geometry%gridpoints)
            ! applied: fixed forces plus the tractions of SET FUP on the
            ! boundary as it is now
            call boundary_traction_force(b, model%geometry, i, tfx, tfy, tdfx, tdfy)
            ax = (b%fx(i) + tfx)*b%xmul(i)
            ay = (b%fy(i) + tfy)*b%ymul(i)
            fx = ax + 0.0_wp     ! + 0: no -0 for a zero total times XMUL < 0
            fy = ay + 0.0_wp
            ! reaction: what the support must cancel, the zone and contact
            ! forces on the gridpoint plus the weight of its own mass (the
            ! reactions of a body on fixed supports add up to its weight)
            ! plus the load stored under the velocity (xmul fx: it goes
            ! straight into the support; the step does not add it to the
            ! gridpoint's force sum), so the reactions add up to the weight
            ! and all applied loads
            ! a corner of a rigid or SDEF block: its share of the block's
            ! held force (rrx, rry above; 0 on a FIXed block)
            if (b%ix(i) == bc_velocity) call held(ax, rrx(i), 1, fx, sx)
            if (b%iy(i) == bc_velocity) call held(ay, rry(i), 2, fy, sy)
            write (text, '(i8,2a,2i4,4a)') c, fmt_real(co%x(c)), fmt_real(co%y(c)), &
               shown_code(b%ix(i), b%vis(i), vis_x), shown_code(b%iy(i), b%vis(i), vis_y), &
               fmt_real(fx), fmt_real(fy), fmt_real(b%dfx(i) + tdfx + 0.0_wp), &
               fmt_real(b%dfy(i) + tdfy + 0.0_wp)
         end associate
      end subroutine forces_row

      !> The reaction f of point i in direction k (1 x, 2 y) held by a
      !> velocity, with the load a stored under it: a gridpoint's force sum
      !> and weight, or rr, a rigid corner's share; a stored load counts in
      !> nheld and its sum st.
      subroutine held(a, rr, k, f, st)
         real(wp), intent(in) :: a, rr
         integer, intent(in) :: k
         real(wp), intent(out) :: f
         real(wp), intent(inout) :: st
         associate (gp => model%geometry%gridpoints)
            if (g > 0) then
               if (k == 1) then
                  f = gp%fx(g) + gp%mass(g)*model%gravity(1) + a + 0.0_wp
               else
                  f = gp%fy(g) + gp%mass(g)*model%gravity(2) + a + 0.0_wp
               end if
            else
               f = rr + a + 0.0_wp
            end if
         end associate
         if (a /= 0.0_wp) nheld = nheld + 1
         st = st + a
      end subroutine held

      !> DISPLACEMENTS row of point i: its displacement (the gridpoint's in a
      !> zoned block) and the prescribed velocity.
      subroutine displacements_row()
         real(wp) :: ux, uy, vx, vy
         associate (b => model%bound, co => model%geometry%corners, &
                    gp => model%geometry%gridpoints)
            if (g > 0) then
               ux = gp%ux(g); uy = gp%uy(g)
            else
               ux = co%ux(c); uy = co%uy(c)
            end if
            vx = 0.0_wp; vy = 0.0_wp
            if (b%ix(i) == bc_velocity) vx = b%vx(i)*b%xmul(i) + 0.0_wp
            if (b%iy(i) == bc_velocity) vy = b%vy(i)*b%ymul(i) + 0.0_wp
            write (text, '(i8,6a)') c, fmt_real(co%x(c)), fmt_real(co%y(c)), fmt_real(ux), &
               fmt_real(uy), fmt_real(vx), fmt_real(vy)
         end associate
      end subroutine displacements_row
   end subroutine boundary_table


   !> SET FUP / -FUP: boundary stresses follow the boundary or keep their direction.
   subroutine set_boundary(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      if (.not. apply) then
         if (parsed%find('FUP') > 0 .and. parsed%find('-FUP') > 0) &
            call set_error(error, 'SET FUP / -FUP: give one of them, not both')
         return
      end if
      call boundary_set_fup(ctx%model, parsed%items(k)%name == 'FUP', ctx%out)
   end subroutine set_boundary

end module commands_boundary
