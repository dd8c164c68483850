!> SET ZPRESS x y rad pz (manual SET): a zone pressure source. The zones are
!> those of live FDEF blocks whose centroid lies within rad of (x, y),
!> chosen now; the source takes the history of the latest BOUNDARY history
!> keyword given since the last CYCLE (CONSTANT if none). State:
!> `model%bound%zp` (model_boundary); kernel: zones_pressure. Reading of the
!> manual: docs/zones.md ("Zone pressure").
module commands_zpress
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t
   use model_state, only: model_t
   use model_boundary, only: zpress_add_source
   use commands_boundary, only: boundary_history_name
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t
   use commands_numbers, only: format_real
   implicit none
   private
   public :: zpress_check, zpress_set, register_zpress_commands

contains

   !> SET ZPRESS in the registry (commands_context).
   subroutine register_zpress_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add_set('zpress', 'ZPress rrrr', set_zpress)
      call reg%note('ZPRESS', unit='m m m Pa')
   end subroutine register_zpress_commands

   !> Check every ZPRESS keyword of a SET line before any keyword acts (a
   !> rejected SET changes nothing).
   subroutine zpress_check(model, parsed, error)
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer(ip), allocatable :: zones(:)
      integer :: k
      do k = 1, parsed%nitems
         if (parsed%items(k)%name /= 'ZPRESS') cycle
         call select_zones(model, parsed, k, zones, error)
         if (allocated(error)) return
      end do
   end subroutine zpress_check

   !> SET ... ZPRESS x y rad pz (item k): add the source, print one line.
   subroutine zpress_set(model, parsed, k, out, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      integer(ip), allocatable :: zones(:)
      character(len=200) :: text
      call select_zones(model, parsed, k, zones, error)
      if (allocated(error)) return
      associate (zp => model%bound%zp)
         call zpress_add_source(zp, parsed%real_at(k, 1), parsed%real_at(k, 2), &
                                parsed%real_at(k, 3), parsed%real_at(k, 4), zones)
         write (text, '(a,i0,a)') 'SET ZPRESS: source ', zp%n, ', pressure '//format_real(zp%pz(zp%n))
         write (text, '(a,i0,a)') trim(text)//' in ', size(zones), ' zone(s), history '// &
            trim(boundary_history_name(zp%h(zp%n)))
      end associate
      call out%line(trim(text))
   end subroutine zpress_set

   !> Live zones of live blocks with centroid within rad of (x, y) (item k).
   subroutine select_zones(model, parsed, k, zones, error)
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      integer(ip), allocatable, intent(out) :: zones(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: x, y, rad, xc, yc
      integer(ip) :: z, n, nlive
      logical, allocatable :: inside(:)
      x = parsed%real_at(k, 1)
      y = parsed%real_at(k, 2)
      rad = parsed%real_at(k, 3)
      if (.not. (rad > 0.0_wp)) then
         call set_error(error, 'SET ZPRESS: expected a radius rad > 0 (x y rad pz), got '// &
                        format_real(rad))
         return
      end if
      associate (zn => model%geometry%zones, gp => model%geometry%gridpoints, &
                 bl => model%geometry%blocks)
         allocate (inside(max(1_ip, zn%n)))
         inside = .false.
         nlive = 0
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            if (.not. bl%live(zn%block(z))) cycle
            nlive = nlive + 1
            xc = (gp%x(zn%g1(z)) + gp%x(zn%g2(z)) + gp%x(zn%g3(z)))/3.0_wp
            yc = (gp%y(zn%g1(z)) + gp%y(zn%g2(z)) + gp%y(zn%g3(z)))/3.0_wp
            inside(z) = (xc - x)**2 + (yc - y)**2 <= rad*rad
         end do
         if (nlive == 0) then
            call set_error(error, 'SET ZPRESS: the model has no zones; the pressure acts in ' &
                           //'zones of FDEF blocks (give GENERATE first)')
            return
         end if
         n = count(inside(1:zn%n))
         if (n == 0) then
            call set_error(error, 'SET ZPRESS: no zone centroid lies within '//format_real(rad)// &
                           ' of ('//format_real(x)//', '//format_real(y)//')')
            return
         end if
         allocate (zones(n))
         n = 0
         do z = 1, zn%n
            if (.not. inside(z)) cycle
            n = n + 1
            zones(n) = z
         end do
      end associate
   end subroutine select_zones

   !> SET ZPRESS x y rad pz: every source of the line is checked before any is added.
   subroutine set_zpress(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      if (.not. apply) then
         if (k == parsed%find('ZPRESS')) call zpress_check(ctx%model, parsed, error)
         return
      end if
      call zpress_set(ctx%model, parsed, k, ctx%out, error)
   end subroutine set_zpress

end module commands_zpress
