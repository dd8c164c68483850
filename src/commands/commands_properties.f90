!> PROPERTY, GRAVITY and PRINT PROPERTY (manual Section 4.5).
module commands_properties
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_properties, only: prop_bulk, prop_shear, property_table, property_aliases, &
                               property_index, nproperties, property_keyword_spec, &
                               joint_material_property
   use core_limits, only: check_request, max_material_number
   use commands_parser, only: parsed_t
   use commands_tokens, only: to_upper
   use commands_context, only: context_t, registry_t, cannot_fail
   implicit none
   private
   public :: register_property_commands
   public :: handle_property, handle_gravity, print_properties

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_property_commands(reg)
      type(registry_t), intent(inout) :: reg
      integer :: k
      ! the keywords, units and defaults are the declarations' (model_properties)
      call reg%add('properties', 'PROperty', '', '', property_keyword_spec(), '4.5', &
                   'material properties of blocks, joints, reinforcement and heat', &
                   handler=handle_property)
      do k = 1, nproperties
         call reg%note(property_table(k)%keyword, unit=trim(property_table(k)%unit), &
                       default=default_text(property_table(k)%default))
      end do
      call reg%add('properties', 'GRavity', 'rr', '', '', '4.5', &
                   'gravitational acceleration, x and y components', run_gravity, &
                   unit='m/s^2', default='0 0', args='gx gy')
      call reg%add_set('properties', 'Gravity rr', set_gravity)
      call reg%note('GRAVITY', unit='m/s^2', default='0 0')
   end subroutine register_property_commands

   !> PROPERTY MAT n | JMAT n keyword v ... : validate every pair, then store.
   !> MAT and JMAT index one table; a later MAT/JMAT on the line switches the
   !> material the following values go to.
   !> A material that gets both BULK and SHEAR for the first time completes
   !> the plane-strain szz = nu (sxx + syy) of zones INSITU stressed before
   !> (INSITU before PROPERTY, as in the manual's verification deck E, left
   !> szz = 0; a Mohr-Coulomb zone then failed at once with szz as its minor
   !> principal stress). Such zones cannot have been cycled: CYCLE refuses
   !> zones without moduli.
   subroutine handle_property(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, mat, first, m
      logical :: joint
      integer, allocatable :: mats(:)
      logical, allocatable :: elastic_before(:)
      associate (model => ctx%model, out => ctx%out)
         first = 0
         do k = 1, parsed%nitems
            if (parsed%items(k)%keyword > 0) then
               first = k
               exit
            end if
         end do
         if (first == 0) then
            call set_error(error, 'PROPERTY: expected MAT n or JMAT n followed by properties')
            return
         end if
         select case (parsed%items(first)%name)
         case ('MATERIAL', 'JMATERIAL')
         case default
            call set_error(error, 'PROPERTY: the first keyword must be MAT n or JMAT n, got ' &
                           //parsed%items(first)%name)
            return
         end select
         ! the table grows to the highest number: refuse a number it cannot hold
         do k = first, parsed%nitems
            if (parsed%items(k)%name /= 'MATERIAL' .and. parsed%items(k)%name /= 'JMATERIAL') cycle
            call check_request('PROPERTY: material number', real(parsed%int_at(k, 1), wp), &
                               real(nproperties*9, wp), real(max_material_number, wp), error)
            if (allocated(error)) return
         end do
         ! One table holds both kinds (the manual's decks give joint keywords to
         ! MAT n: Appendix decks `PROP M=1 D=... JKN=...`, the grout's JKS JCOH
         ! and the liner interface's KN KS of Section 4.5), but a block keyword
         ! after JMAT n is a slip: `PROP JMAT=1 FRIC=30` meant the joint and
         ! set the friction of the blocks of material 1. Refused, naming the
         ! joint keywords meant.
         joint = .false.
         do k = first, parsed%nitems
            select case (parsed%items(k)%name)
            case ('MATERIAL'); joint = .false.
            case ('JMATERIAL'); joint = .true.
            case default
               if (.not. joint .or. joint_material_property(parsed%items(k)%name)) cycle
               call set_error(error, 'PROPERTY: '//parsed%items(k)%name// &
                              ' is a block property, given to MAT n, not to JMAT n'// &
                              joint_counterpart(parsed%items(k)%name)// &
                              ' (manual Section 4.5, PROPERTY: Joint Material Properties)')
               return
            end select
         end do
         ! Names, abbreviations and ranges were checked by the parser against the
         ! declarations (model_properties: PROPERTY's keyword table is generated
         ! from them); nothing more can fail, so store.
         allocate (mats(0), elastic_before(0))
         do k = first, parsed%nitems
            if (parsed%items(k)%name /= 'MATERIAL' .and. parsed%items(k)%name /= 'JMATERIAL') cycle
            m = parsed%int_at(k, 1)
            mats = [mats, m]
            elastic_before = [elastic_before, has_moduli(model, m)]
         end do
         mat = 0
         do k = first, parsed%nitems
            select case (parsed%items(k)%name)
            case ('MATERIAL', 'JMATERIAL')
               mat = parsed%int_at(k, 1)
            case default
               call store(parsed%items(k)%name, parsed%real_at(k, 1))
               call note_angle_like(parsed%items(k)%name, parsed%real_at(k, 1))
            end select
         end do
         do k = 1, size(mats)
            if (.not. elastic_before(k) .and. has_moduli(model, mats(k))) &
               call complete_insitu_szz(model, mats(k), out)
         end do
      end associate
   contains
      !> The manual's friction and dilation properties are coefficients, the
      !> tangent of the angle (Section 4.5 PROPERTY: "[tangent of friction
      !> angle]"); a value from 5 to 60 looks like an angle in degrees (a new
      !> user wrote JFRIC=30 from a note that said degrees, and the joint held
      !> at 88 degrees). Said, not refused: the manual's decks glue joints
      !> with JFRIC=10 or 100 on purpose.
      subroutine note_angle_like(name, value)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: value
         character(len=200) :: text
         select case (name)
         case ('JFRIC', 'JDIL', 'CFRICTION', 'CDILATION', 'FRICTION', 'DILATION')
            if (value < 5.0_wp .or. value > 60.0_wp) return
            write (text, '(4a,f0.1,a,f0.1,a,f6.4)') 'note: PROPERTY ', name, &
               ' is a coefficient, the tangent of the angle (manual Section 4.5): ', &
               'this value means ', atan(value)*180.0_wp/acos(-1.0_wp), ' degrees; for ', value, &
               ' degrees give ', tan(value*acos(-1.0_wp)/180.0_wp)
            call ctx%out%line(trim(text))
         end select
      end subroutine note_angle_like
      !> A declared property by its name, or an alias (K, G, COND) by its ids.
      subroutine store(name, value)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: value
         integer :: a, id
         do a = 1, size(property_aliases)
            if (to_upper(property_aliases(a)%keyword) /= name) cycle
            do id = property_aliases(a)%first, property_aliases(a)%last
               call ctx%model%materials%set(mat, id, value)
            end do
            return
         end do
         call ctx%model%materials%set(mat, property_index(name), value)
      end subroutine store
   end subroutine handle_property

   !> The joint keywords a block keyword given to JMAT n may have meant.
   function joint_counterpart(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      select case (name)
      case ('FRICTION'); text = '; the joint friction is JFRIC (JCONS 2, 3, 5) or CFRIC (JCONS 1)'
      case ('COHESION'); text = '; the joint cohesion is JCOH (JCONS 2, 3, 5) or CCOH (JCONS 1)'
      case ('TENSILE'); text = '; the joint tensile strength is JTENS (JCONS 2, 3, 5) or CTENS (JCONS 1)'
      case ('DILATION'); text = '; the joint dilation is JDIL (JCONS 2, 3, 5) or CDIL (JCONS 1)'
      case ('BULK', 'K'); text = '; the joint normal stiffness is JKN (JCONS 2, 3, 5) or KN (JCONS 1)'
      case ('SHEAR', 'G'); text = '; the joint shear stiffness is JKS (JCONS 2, 3, 5) or KS (JCONS 1)'
      case default; text = '; JMAT n takes KN KS CCOH CPERM CDIL CFRIC CTENS AZERO ARES JKN JKS '// &
                           'JCOH JDIL JFRIC JPERM JTENS JEN JES JIF JR'
      end select
   end function joint_counterpart

   logical function has_moduli(model, m)
      type(model_t), intent(in) :: model
      integer, intent(in) :: m
      has_moduli = model%materials%get(m, prop_bulk) > 0.0_wp .and. &
                   model%materials%get(m, prop_shear) > 0.0_wp
   end function has_moduli

   !> szz = nu (sxx + syy) in the live zones of material-m blocks that carry
   !> in-plane stresses and szz = 0 (see handle_property).
   subroutine complete_insitu_szz(model, m, out)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: m
      type(output_t), intent(inout), optional :: out
      integer(ip) :: z, b, n
      real(wp) :: kb, gs, nu
      character(len=160) :: text
      kb = model%materials%get(m, prop_bulk)
      gs = model%materials%get(m, prop_shear)
      nu = (3.0_wp*kb - 2.0_wp*gs)/(2.0_wp*(3.0_wp*kb + gs))
      n = 0
      associate (zn => model%geometry%zones, bl => model%geometry%blocks)
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            b = zn%block(z)
            if (.not. bl%live(b) .or. bl%material(b) /= m) cycle
            if (zn%szz(z) /= 0.0_wp) cycle
            if (zn%sxx(z) == 0.0_wp .and. zn%syy(z) == 0.0_wp) cycle
            zn%szz(z) = nu*(zn%sxx(z) + zn%syy(z))
            n = n + 1
         end do
      end associate
      if (n > 0 .and. present(out)) then
         write (text, '(a,i0,a,i0,a)') 'Note: szz = nu (sxx + syy) set in ', n, &
            ' zone(s) of material ', m, ' stressed by INSITU before its K and G were given'
         call out%line(trim(text))
      end if
   end subroutine complete_insitu_szz

   !> GRAVITY gx gy (also SET GRAVITY).
   subroutine handle_gravity(model, gx, gy)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: gx, gy
      model%gravity = [gx, gy]
   end subroutine handle_gravity

   !> PRINT PROPERTY: every material with its given properties, fixed columns.
   !> With `only`, just the property ids listed there (PRINT PROPERTY <kind>).
   subroutine print_properties(model, out, only)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      integer, intent(in), optional :: only(:)
      integer :: mat, k
      logical :: any_printed
      character(len=80) :: line
      call out%line('')
      call out%line('  material  property        value')
      call out%line('  --------  ----------  --------------')
      any_printed = .false.
      do mat = 1, model%materials%nmat
         do k = 1, nproperties
            if (.not. model%materials%given(k, mat)) cycle
            if (present(only)) then
               if (all(only /= k)) cycle
            end if
            write (line, '(2x,i8,2x,a10,2x,a)') mat, property_table(k)%name, &
               fmt_real(model%materials%value(k, mat), 14, 6)
            call out%line(line)
            any_printed = .true.
         end do
      end do
      if (.not. any_printed) call out%line('  (no properties given)')
   end subroutine print_properties

   !> A declared default as HELP shows it: a whole number plainly, else in E format.
   function default_text(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      character(len=24) :: buf
      if (v == aint(v) .and. abs(v) < 1.0e9_wp) then
         write (buf, '(i0)') int(v)
      else
         buf = fmt_real(v, 12, 4)
      end if
      text = trim(adjustl(buf))
   end function default_text

   subroutine run_gravity(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_gravity(ctx%model, parsed%real_at(1, 1), parsed%real_at(1, 2))
      call cannot_fail(error)
   end subroutine run_gravity


   !> SET GRAVITY gx gy (as GRAVITY).
   subroutine set_gravity(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error)
      if (.not. apply) return
      call handle_gravity(ctx%model, parsed%real_at(k, 1), parsed%real_at(k, 2))
   end subroutine set_gravity

end module commands_properties
