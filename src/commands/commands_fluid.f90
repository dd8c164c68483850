!> Fluid-flow commands (manual Sections 3.12 and 4.5): FLUID, PFIX, PFREE,
!> the fluid keywords of SET (CAPRATIO, SFLOW, -SFLOW, EFF, -EFF, YWTABLE,
!> PTOL) and of BOUNDARY (PP, PGRAD, IMPERMEABLE), PRINT FLOWS and the
!> pressure table of PRINT DOMAINS / PRINT FLUID. The first of them creates
!> the model's fluid part (model_fluid); a model without it runs no fluid
!> code. Physics: src/fluid/fluid_flow.f90.
module commands_fluid
   use commands_address, only: resolve_entity
   use model_address, only: ak_domain, domain_centre
   use core_kinds, only: wp, ip
   use core_range, only: range_t, in_range
   use core_error, only: error_t, set_error
   use core_output, only: output_t, itoa, fmt_real
   use commands_numbers, only: format_real
   use model_state, only: model_t
   use model_fluid, only: fluid_t, fluid_size, bnd_open, bnd_pressure, bnd_impermeable
   use contact_refresh, only: geometry_refresh
   use fluid_flow, only: fluid_sync, fluid_boundary_contact, fluid_positions
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t
   implicit none
   private
   public :: register_fluid_commands
   public :: handle_fluid, handle_pfix, handle_pfree, set_fluid_keyword
   public :: boundary_fluid, boundary_fluid_check, print_flows, print_fluid_domains
   public :: print_boundary_fluid, insitu_pore_pressures

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_fluid_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('fluid', 'FLuid', '[n[n[n]]]', '', 'Rhow n;DENsity n;Bulkw n;Cohw n', '4.5', &
                   'fluid properties: density, bulk modulus, cohesion of the joint fluid', &
                   handler=handle_fluid)
      call reg%note('RHOW DENSITY', unit='kg/m^3')
      call reg%note('BULKW COHW', unit='Pa')
      call reg%add('fluid', 'PFix', '[R]', '', 'Domain q;Pressure r;Xgrad r;Ygrad r', '4.5', &
                   'fix the fluid pressure of domains', handler=handle_pfix)
      call reg%note('PRESSURE', unit='Pa')
      call reg%note('XGRAD YGRAD', unit='Pa/m')
      call reg%add('fluid', 'PFRee', 'c', '', '', '4.5', 'free a domain pressure PFIX held', &
                   handler=handle_pfree, args='ia')
      call reg%add_set('fluid', 'CAPratio p;EFF;-EFF;Ptol p;SFlow;-SFlow;YWtable r', &
                       act=set_fluid_keyword)
      call reg%note('YWTABLE', unit='m', default='1e20 (above every block)')
      call reg%note('CAPRATIO', default='5')
      call reg%note('PTOL', unit='Pa', default='0.01')
      call reg%note('EFF -SFLOW', default='(the default)')
   end subroutine register_fluid_commands

   !> The fluid part, created with its defaults if the model has none.
   subroutine ensure_fluid(model)
      type(model_t), intent(inout) :: model
      if (.not. allocated(model%fluid)) allocate (model%fluid)
   end subroutine ensure_fluid

   !> Domains up to date (geometry only; the fluid part is not touched, so a
   !> command can still reject its line after this).
   subroutine refresh_domains(model, what, error)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (.not. model%geometry%block_created) then
         call set_error(error, what//': no BLOCK has been created (domains are the spaces '// &
                        'between blocks)')
         return
      end if
      call geometry_refresh(model%geometry)
   end subroutine refresh_domains

   !> The fluid part (created if need be) matched to the refreshed domains.
   subroutine attach_fluid(model)
      type(model_t), intent(inout) :: model
      call ensure_fluid(model)
      call fluid_sync(model%fluid, model%geometry)
      call fluid_positions(model%fluid, model%geometry)
   end subroutine attach_fluid

   !> INSITU under SET -EFF (manual Section 4.5, INSITU: "in-situ fluid
   !> pressures are also initialized (fluid density, gravity (if present) and
   !> water table location must be previously defined)"): the domains whose
   !> position lies in `range` and below the water table get the hydrostatic
   !> pressure rhow |gy| (ywtab - y) (PFIXed ones keep theirs). `pc`: each
   !> contact's pressure, the mean of its sides' inner domains, which its
   !> joint does not carry: INSITU gives the joints the effective normal
   !> force (the pressure acts on the block faces, manual Section 3.12). Not
   !> allocated when the model has no total-pressure fluid (SET EFF, the
   !> default, takes the water's weight as buoyancy instead).
   subroutine insitu_pore_pressures(model, range, out, pc, error)
      type(model_t), intent(inout) :: model
      type(range_t), intent(in) :: range
      type(output_t), intent(in) :: out
      real(wp), allocatable, intent(out) :: pc(:)
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: d, c, n, s, dd
      real(wp) :: g, sum
      if (.not. allocated(model%fluid)) return
      if (model%fluid%eff) return
      g = -model%gravity(2)
      if (.not. model%fluid%rhow > 0.0_wp .or. .not. g > 0.0_wp .or. &
          model%fluid%ywtab >= 1.0e19_wp) then
         call out%line('INSITU: note: SET -EFF: no fluid pressures set (they need FLUID DENS, '// &
                       'GRAVITY with a downward y component and SET YWTABLE before INSITU, '// &
                       'manual Section 4.5)')
         return
      end if
      call ready_domains(model, 'INSITU', error)
      if (allocated(error)) return
      n = 0
      associate (fl => model%fluid, dm => model%geometry%domains, ct => model%geometry%contacts)
         do d = 1, dm%n
            if (.not. dm%live(d) .or. dm%outer(d) .or. fl%fixed(d)) cycle
            if (.not. range%contains_point(fl%xd(d), fl%yd(d))) cycle
            fl%p(d) = fl%rhow*g*max(fl%ywtab - fl%yd(d), 0.0_wp)
            n = n + 1
         end do
         allocate (pc(ct%n))
         pc = 0.0_wp
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            sum = 0.0_wp
            s = 0
            do dd = 1, 2
               d = merge(ct%dom1(c), ct%dom2(c), dd == 1)
               if (d < 1 .or. d > dm%n) cycle
               if (dm%outer(d)) cycle
               sum = sum + fl%p(d)
               s = s + 1
            end do
            if (s > 0) pc(c) = sum/real(s, wp)
         end do
      end associate
      call out%line('INSITU: fluid pressures set in '//itoa(int(n))//' domains from the water '// &
                    'table (SET -EFF); the joints carry the effective normal stress')
   end subroutine insitu_pore_pressures

   !> Domains up to date and the pressures matched to them.
   subroutine ready_domains(model, what, error)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      call refresh_domains(model, what, error)
      if (allocated(error)) return
      call attach_fluid(model)
   end subroutine ready_domains

   !> The model has fluid and its domains are ready for `what` (PRINT FLOWS,
   !> PRINT FLUID); else says why not on `out`.
   logical function fluid_printable(model, what, out) result(ok)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: what
      type(output_t), intent(in) :: out
      type(error_t), allocatable :: error
      ok = .false.
      if (.not. allocated(model%fluid)) then
         call out%line(what//': no fluid in the model (give FLUID first)')
         return
      end if
      call ready_domains(model, what, error)
      if (allocated(error)) then
         call out%line(what//': '//error%message)
         return
      end if
      ok = .true.
   end function fluid_printable

   !> FLUID rhow bulkw cohw, positional or as RHOW (DENSITY) / BULKW / COHW.
   subroutine handle_fluid(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v(3)
      logical :: given(3)
      integer :: k, j
      character(len=5), parameter :: names(3) = ['RHOW ', 'BULKW', 'COHW ']
      associate (model => ctx%model, out => ctx%out)
         given = .false.
         v = 0.0_wp
         do k = 1, parsed%nitems
            select case (parsed%items(k)%name)
            case ('')
               do j = 1, min(3, parsed%items(k)%count)
                  v(j) = parsed%real_at(k, j)
                  given(j) = .true.
               end do
            case ('RHOW', 'DENSITY')
               v(1) = parsed%real_at(k, 1); given(1) = .true.
            case ('BULKW')
               v(2) = parsed%real_at(k, 1); given(2) = .true.
            case ('COHW')
               v(3) = parsed%real_at(k, 1); given(3) = .true.
            end select
         end do
         if (.not. any(given)) then
            call set_error(error, 'FLUID: expected the fluid density, bulk modulus and yield '// &
                           'strength (FLUID rhow bulkw <cohw>, or RHOW= BULKW= COHW=)')
            return
         end if
         do j = 1, 3
            if (given(j) .and. v(j) < 0.0_wp) then
               call set_error(error, 'FLUID '//trim(names(j))//' '//trim(format_real(v(j)))// &
                              ': expected a value >= 0')
               return
            end if
         end do
         call ensure_fluid(model)
         if (given(1)) model%fluid%rhow = v(1)
         if (given(2)) model%fluid%bulkw = v(2)
         if (given(3)) model%fluid%cohw = v(3)
         if (given(3) .and. v(3) > 0.0_wp) &
            call out%line('FLUID: Bingham fluid, COHW '//trim(format_real(v(3)))// &
                          ': a joint carries flow above the gradient 2 COHW / aperture')
      end associate
   end subroutine handle_fluid

   !> PFIX <range | DOMAIN n> PRESSURE p <XGRAD dx> <YGRAD dy>.
   subroutine handle_pfix(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: kd, kp, kx, ky
      integer(ip) :: d, dom, n
      real(wp) :: p, gx, gy
      associate (model => ctx%model, out => ctx%out)
         kd = parsed%find('DOMAIN')
         kp = parsed%find('PRESSURE')
         kx = parsed%find('XGRAD')
         ky = parsed%find('YGRAD')
         if (kp == 0 .and. kx == 0 .and. ky == 0) then
            call set_error(error, 'PFIX: expected PRESSURE p (and optionally XGRAD dx, YGRAD dy)')
            return
         end if
         if (kd > 0 .and. parsed%has_range) then
            call set_error(error, 'PFIX: give a range or DOMAIN n, not both')
            return
         end if
         p = 0.0_wp; gx = 0.0_wp; gy = 0.0_wp
         if (kp > 0) p = parsed%real_at(kp, 1)
         if (kx > 0) gx = parsed%real_at(kx, 1)
         if (ky > 0) gy = parsed%real_at(ky, 1)
         dom = 0
         if (kd > 0) dom = int(parsed%int_at(kd, 1), ip)
         if (kd > 0 .and. dom < 1) then
            call set_error(error, 'PFIX DOMAIN '//itoa(int(dom))//': expected a domain number >= 1')
            return
         end if
         ! check everything before the fluid part is created or changed
         call refresh_domains(model, 'PFIX', error)
         if (allocated(error)) return
         ! DOMAIN n: the 1989 address of the domain (manual Section 4.5 PFIX)
         if (dom > 0) then
            call resolve_entity(model, ak_domain, dom, 'PFIX DOMAIN', out, d, error)
            if (allocated(error)) return
            dom = d
         end if
         associate (dm => model%geometry%domains)
            if (dom > 0) then
               if (.not. dm%live(dom) .or. dm%outer(dom)) then
                  call set_error(error, 'PFIX DOMAIN '//itoa(int(dom))// &
                                 ': the outer domain has no fluid pressure (use BOUNDARY PP)')
                  return
               end if
            end if
         end associate
         call attach_fluid(model)
         associate (fl => model%fluid, dm => model%geometry%domains)
            n = 0
            do d = 1, dm%n
               if (.not. dm%live(d) .or. dm%outer(d)) cycle
               if (dom > 0 .and. d /= dom) cycle
               if (dom == 0 .and. parsed%has_range) then
                  if (.not. parsed%range%contains_point(fl%xd(d), fl%yd(d))) cycle
               end if
               fl%p(d) = p + gx*fl%xd(d) + gy*fl%yd(d)
               fl%fixed(d) = .true.
               n = n + 1
            end do
            call out%line('PFIX: pressure fixed in '//itoa(int(n))//' domains')
         end associate
      end associate
   end subroutine handle_pfix

   !> PFREE ia: domain ia (0: all) no longer has its pressure fixed.
   subroutine handle_pfree(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: ia, d
      associate (model => ctx%model, out => ctx%out)
         ia = int(parsed%int_at(1, 1), ip)
         call refresh_domains(model, 'PFREE', error)
         if (allocated(error)) return
         if (ia < 0) then
            call set_error(error, 'PFREE '//itoa(int(ia))//': expected a domain address (0 ' // &
                                     'frees all)')
            return
         end if
         ! ia: the 1989 address of the domain (manual Section 4.5 PFREE)
         if (ia > 0) then
            call resolve_entity(model, ak_domain, ia, 'PFREE', out, d, error)
            if (allocated(error)) return
            ia = d
         end if
         call attach_fluid(model)
         if (ia == 0) then
            model%fluid%fixed(1:model%fluid%nd) = .false.
         else
            model%fluid%fixed(ia) = .false.
         end if
         call out%line('PFREE: done')
      end associate
   end subroutine handle_pfree

   !> SET CAPRATIO r, SFLOW, -SFLOW, EFF, -EFF, YWTABLE y, PTOL p (item k).
   subroutine set_fluid_keyword(model, parsed, k)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      call ensure_fluid(model)
      call parsed%take(k, 'CAPRATIO', model%fluid%capratio)
      call parsed%take(k, 'SFLOW', model%fluid%sflow)
      call parsed%take(k, 'EFF', model%fluid%eff)
      call parsed%take(k, 'YWTABLE', model%fluid%ywtab)
      call parsed%take(k, 'PTOL', model%fluid%ptol)
      ! a new PTOL is weighed against the pressures afresh (engine_cycle)
      if (parsed%items(k)%name == 'PTOL') model%fluid%ptol_noted = .false.
   end subroutine set_fluid_keyword

   !> Check the fluid keywords of a BOUNDARY line (PP, PGRAD, IMPERMEABLE)
   !> without changing the fluid part; the domains are refreshed.
   subroutine boundary_fluid_check(model, parsed, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: kp, kg, ki
      kp = parsed%find('PP')
      kg = parsed%find('PGRAD')
      ki = parsed%find('IMPERMEABLE')
      if (kp == 0 .and. kg == 0 .and. ki == 0) return
      if (ki > 0 .and. (kp > 0 .or. kg > 0)) then
         call set_error(error, 'BOUNDARY IMPERMEABLE: give it alone, not with PP / PGRAD')
         return
      end if
      if (parsed%find('CORNER') > 0) then
         call set_error(error, 'BOUNDARY CORNER: PP / PGRAD / IMPERMEABLE select boundary '// &
                        'contacts by a range xl xu yl yu, not by corners')
         return
      end if
      call refresh_domains(model, 'BOUNDARY '//trim(merge('IMPERMEABLE', 'PP         ', ki > 0)), error)
   end subroutine boundary_fluid_check

   !> BOUNDARY <range> PP p <PGRAD g> | IMPERMEABLE: the contacts on the
   !> outer domain whose point lies in the range link their domain to a
   !> reservoir at pressure p + g y, or carry no flow. The line has passed
   !> boundary_fluid_check (and the rest of BOUNDARY's checks): nothing fails.
   subroutine boundary_fluid(model, parsed, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      integer :: kp, kg, ki, side
      integer(ip) :: c, n
      real(wp) :: p, g
      logical :: onb
      kp = parsed%find('PP')
      kg = parsed%find('PGRAD')
      ki = parsed%find('IMPERMEABLE')
      if (kp == 0 .and. kg == 0 .and. ki == 0) return
      p = 0.0_wp
      g = 0.0_wp
      if (kp > 0) p = parsed%real_at(kp, 1)
      if (kg > 0) g = parsed%real_at(kg, 1)
      call attach_fluid(model)
      n = 0
      associate (fl => model%fluid, ct => model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            call fluid_boundary_contact(model%geometry, c, side, onb)
            if (.not. onb) cycle
            if (.not. parsed%range%contains_point(ct%x(c), ct%y(c))) cycle
            if (ki > 0) then
               fl%bnd_code(c) = bnd_impermeable
               fl%bnd_p(c) = 0.0_wp
               fl%bnd_g(c) = 0.0_wp
            else
               fl%bnd_code(c) = bnd_pressure
               fl%bnd_p(c) = p
               fl%bnd_g(c) = g
            end if
            n = n + 1
         end do
      end associate
      if (ki > 0) then
         call out%line('BOUNDARY IMPERMEABLE: '//itoa(int(n))//' boundary contacts')
      else
         call out%line('BOUNDARY PP: '//itoa(int(n))//' boundary contacts')
      end if
   end subroutine boundary_fluid

   !> PRINT FLOWS: flow rate of every contact that carries one (from the
   !> domain DOM1 to DOM2; at the boundary, INFLOW is positive into the model)
   !> and the totals through the boundary.
   subroutine print_flows(model, out)
      type(model_t), intent(inout) :: model
      type(output_t), intent(in) :: out
      integer(ip) :: c
      integer :: side
      logical :: onb
      real(wp) :: qin, qout, inflow
      character(len=160) :: line
      if (.not. fluid_printable(model, 'PRINT FLOWS', out)) return
      qin = 0.0_wp
      qout = 0.0_wp
      call out%line(' CONTACT    DOM1    DOM2             X             Y      APERTURE'// &
                    '     FLOW RATE        INFLOW')
      associate (fl => model%fluid, ct => model%geometry%contacts)
         do c = 1, min(ct%n, fl%nc)
            if (.not. ct%live(c)) cycle
            if (fl%q(c) == 0.0_wp) cycle
            call fluid_boundary_contact(model%geometry, c, side, onb)
            if (onb) then
               inflow = merge(fl%q(c), -fl%q(c), side == 2)
               if (inflow > 0.0_wp) qin = qin + inflow
               if (inflow < 0.0_wp) qout = qout - inflow
               write (line, '(3i8,5(1x,a13))') c, ct%dom1(c), ct%dom2(c), format_real(ct%x(c)), &
                  format_real(ct%y(c)), format_real(fl%aperture(c)), format_real(fl%q(c)), &
                  format_real(inflow)
            else
               write (line, '(3i8,4(1x,a13))') c, ct%dom1(c), ct%dom2(c), format_real(ct%x(c)), &
                  format_real(ct%y(c)), format_real(fl%aperture(c)), format_real(fl%q(c))
            end if
            call out%line(trim(line))
         end do
      end associate
      call out%line('total boundary inflow  '//format_real(qin))
      call out%line('total boundary outflow '//format_real(qout))
   end subroutine print_flows

   !> PRINT FLUID (and PRINT DOMAINS in a model with fluid): pressure,
   !> fluid volume, position and fixed flag of every domain (under SET -EFF
   !> a dry domain prints pressure 0); with a range, of the domains whose
   !> centre lies in it (as PRINT DOMAINS selects them).
   subroutine print_fluid_domains(model, out, range)
      type(model_t), intent(inout) :: model
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: d
      real(wp) :: p, xm, ym
      character(len=160) :: line
      if (.not. fluid_printable(model, 'PRINT FLUID', out)) return
      call out%line('  DOMAIN      PRESSURE        VOLUME             X             Y FIXED')
      associate (fl => model%fluid, dm => model%geometry%domains)
         do d = 1, dm%n
            if (.not. dm%live(d) .or. dm%outer(d)) cycle
            if (present(range)) then
               call domain_centre(model%geometry, d, xm, ym)
               if (.not. in_range(xm, ym, range)) cycle
            end if
            p = fl%p(d)
            if (.not. fl%eff) p = max(p, 0.0_wp)
            write (line, '(i8,4(1x,a13),1x,l5)') d, format_real(p), format_real(fl%vol(d)), &
               format_real(fl%xd(d)), format_real(fl%yd(d)), fl%fixed(d)
            call out%line(trim(line))
         end do
      end associate
   end subroutine print_fluid_domains


   !> PRINT BOUNDARY FLUID: the fluid condition of every contact on the outer
   !> domain (BOUNDARY PP / PGRAD / IMPERMEABLE; open to a reservoir at
   !> pressure 0 unless given), with the pressure it imposes there.
   subroutine print_boundary_fluid(model, out, range)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: c, n
      integer :: side
      logical :: onb
      character(len=160) :: text
      character(len=:), allocatable :: cond
      real(wp) :: p
      if (.not. allocated(model%fluid)) then
         call out%line('  no fluid boundary conditions (no FLUID, BOUNDARY PP or IMPERMEABLE ' &
                       //'has been given): every boundary joint is open at pressure 0')
         return
      end if
      call out%line('  fluid boundary conditions (contacts on the outer boundary)')
      call out%line(' CONTACT             X             Y  CONDITION         PRESSURE')
      n = 0
      associate (fl => model%fluid, ct => model%geometry%contacts)
         do c = 1, min(ct%n, fl%nc)
            if (.not. ct%live(c)) cycle
            call fluid_boundary_contact(model%geometry, c, side, onb)
            if (.not. onb) cycle
            if (present(range)) then
               if (.not. range%contains_point(ct%x(c), ct%y(c))) cycle
            end if
            select case (fl%bnd_code(c))
            case (bnd_pressure)
               cond = 'PP         '
               p = fl%bnd_p(c) + fl%bnd_g(c)*ct%y(c)
            case (bnd_impermeable)
               cond = 'IMPERMEABLE'
               p = 0.0_wp
            case default
               cond = 'open       '
               p = 0.0_wp
            end select
            if (cond == 'IMPERMEABLE') then
               write (text, '(i8,2a,2x,a)') c, fmt_real(ct%x(c)), fmt_real(ct%y(c)), &
                  'IMPERMEABLE      (no flow)'
            else
               write (text, '(i8,2a,2x,a11,a)') c, fmt_real(ct%x(c)), fmt_real(ct%y(c)), &
                  cond, fmt_real(p)
            end if
            call out%line(trim(text))
            n = n + 1
         end do
      end associate
      call out%line('  '//itoa(n)//' boundary contact(s)')
   end subroutine print_boundary_fluid

end module commands_fluid
