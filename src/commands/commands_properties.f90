!> PROPERTY, GRAVITY and PRINT PROPERTY (manual Section 4.5).
module commands_properties
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_materials, only: canonical_property, property_names, &
                              nproperties
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, cannot_fail
   implicit none
   private
   public :: register_property_commands
   public :: handle_property, handle_gravity, print_properties

contains

   !> PROPERTY MAT n | JMAT n keyword v ... : validate every pair, then store.
   !> MAT and JMAT index one table; a later MAT/JMAT on the line switches the
   !> material the following values go to.
   !> A material that gets both BULK and SHEAR for the first time completes
   !> the plane-strain szz = nu (sxx + syy) of zones INSITU stressed before
   !> (INSITU before PROPERTY, as in the manual's verification deck E, left
   !> szz = 0; a Mohr-Coulomb zone then failed at once with szz as its minor
   !> principal stress). Such zones cannot have been cycled: CYCLE refuses
   !> zones without moduli.
   subroutine handle_property(model, parsed, error, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(inout), optional :: out
      integer :: k, mat, first, m
      integer, allocatable :: mats(:)
      logical, allocatable :: elastic_before(:)
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
      ! All values were range-checked by the parser (properties are >= 0, except
      ! the exponents JEN/JES and AZERO); nothing more can fail, so store.
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
         case ('COND')
            call model%materials%set(mat, 'XCOND', parsed%real_at(k, 1))
            call model%materials%set(mat, 'YCOND', parsed%real_at(k, 1))
         case default
            call model%materials%set(mat, canonical_property(parsed%items(k)%name), &
                                     parsed%real_at(k, 1))
         end select
      end do
      do k = 1, size(mats)
         if (.not. elastic_before(k) .and. has_moduli(model, mats(k))) &
            call complete_insitu_szz(model, mats(k), out)
      end do
   end subroutine handle_property

   logical function has_moduli(model, m)
      type(model_t), intent(in) :: model
      integer, intent(in) :: m
      has_moduli = model%materials%get(m, 'BULK') > 0.0_wp .and. &
                   model%materials%get(m, 'SHEAR') > 0.0_wp
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
      kb = model%materials%get(m, 'BULK')
      gs = model%materials%get(m, 'SHEAR')
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
   !> With `only`, just the properties named there (PRINT PROPERTY <kind>).
   subroutine print_properties(model, out, only)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      character(len=*), intent(in), optional :: only(:)
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
               if (all(only /= property_names(k))) cycle
            end if
            write (line, '(2x,i8,2x,a10,2x,a)') mat, property_names(k), &
               fmt_real(model%materials%value(k, mat), 14, 6)
            call out%line(line)
            any_printed = .true.
         end do
      end do
      if (.not. any_printed) call out%line('  (no properties given)')
   end subroutine print_properties

   !> The commands of this family in the registry (commands_context).
   subroutine register_property_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('properties', 'PROperty', '', '', 'Material q;JMaterial q;KN n;KS n;' // &
                   'CCohesion n;CPerm n;CDilation n;CFriction n;CTensile n;AZero r;ARes n;' // &
                   'JKN n;JKS n;JCoh n;JDil n;JFric n;JPerm n;JTensile n;JEN r;JES r;JIF n;' // &
                   'JR n;Bulk n;K n;SHear n;G n;Density n;Cohesion n;Friction n;Tensile n;' // &
                   'DIlation n;TF n;HBS n;HBM n;Ucs n;YComp n;Yield n;RAStiff n;RSStiff n;' // &
                   'RLength n;RUAXial n;RUShear n;RRFac n;RSExp n;RAExp n;CONd n;SPecheat n;' // &
                   'THEXP n;XCOnd n;YCOnd n', '4.5', &
                   'material properties of blocks, joints, reinforcement and heat', run_property)
      call reg%note('KN', unit='N/m', default='0')
      call reg%note('KS', unit='N/m', default='0')
      call reg%note('CCOHESION', unit='N')
      call reg%note('CTENSILE', unit='N')
      call reg%note('CFRICTION', unit='degrees')
      call reg%note('CDILATION', unit='degrees')
      call reg%note('AZERO', unit='m')
      call reg%note('ARES', unit='m')
      call reg%note('JKN', unit='Pa/m', default='0')
      call reg%note('JKS', unit='Pa/m', default='0')
      call reg%note('JCOH', unit='Pa', default='0')
      call reg%note('JDIL', unit='degrees', default='0')
      call reg%note('JFRIC', unit='degrees', default='0')
      call reg%note('JTENSILE', unit='Pa', default='0')
      call reg%note('BULK', unit='Pa')
      call reg%note('K', unit='Pa')
      call reg%note('SHEAR', unit='Pa')
      call reg%note('G', unit='Pa')
      call reg%note('DENSITY', unit='kg/m^3')
      call reg%note('COHESION', unit='Pa')
      call reg%note('FRICTION', unit='degrees')
      call reg%note('TENSILE', unit='Pa')
      call reg%note('DILATION', unit='degrees')
      call reg%note('UCS', unit='Pa')
      call reg%note('RLENGTH', unit='m')
      call reg%note('RUAXIAL', unit='N')
      call reg%note('RUSHEAR', unit='N')
      call reg%note('COND', unit='W/(m K)')
      call reg%note('SPECHEAT', unit='J/(kg K)')
      call reg%note('THEXP', unit='1/K')
      call reg%note('XCOND', unit='W/(m K)')
      call reg%note('YCOND', unit='W/(m K)')
      call reg%add('properties', 'GRavity', 'rr', '', '', '4.5', &
                   'gravitational acceleration, x and y components', run_gravity)
      call reg%note('', unit='m/s^2', default='0 0')
      call reg%add_set('properties', 'Gravity rr', set_gravity)
      call reg%note('GRAVITY', unit='m/s^2', default='0 0')
   end subroutine register_property_commands

   subroutine run_property(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_property(ctx%model, parsed, error, ctx%out)
   end subroutine run_property

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
