!> STRUCTURE (manual Section 4.5) and PRINT STE / STC / LM: structural
!> elements (liners), their interfaces with the rock and their lumped masses.
module commands_structure
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_structures, only: structure_t, iface_broken, iface_slip
   use structure_generate, only: structure_build
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, require_block
   use commands_reinforce, only: handle_reinforcement
   implicit none
   private
   public :: register_structure_commands
   public :: handle_structure, structure_print

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_structure_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('structure', 'STRUcture', 'rrrrqqp[r]', '', '', '4.5', &
                   'beam elements (a liner) along an arc or a line', handler=handle_structure, &
                   args='xc yc fang rrange npoin mat thick [ang]')
      call reg%add('structure', 'CABLe', 'rrrrqqpq[r]', '', '', '4.5', &
                   'grouted reinforcing cable between two points (zoned or rigid blocks)', &
                   handler=handle_reinforcement, &
                   args='x1 y1 x2 y2 npoin mats asteel matg [preten]')
      call reg%add('structure', 'REInforce', 'qrrrr', '', '', '4.5', &
                   'reinforcement across the joints a line crosses', &
                   handler=handle_reinforcement, args='mat x1 y1 x2 y2')
   end subroutine register_structure_commands

   !> STRUCTURE xc yc fang rrange npoin mat thick <ang>. The first STRUCTURE of
   !> a model creates its structure lists; a refused command changes nothing.
   subroutine handle_structure(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(structure_t) :: st
      real(wp) :: ang
      integer(ip) :: n0, e0
      character(len=160) :: line
      associate (model => ctx%model, out => ctx%out)
         call require_block(model, 'STRUCTURE', error)
         if (allocated(error)) return
         ang = 360.0_wp
         if (parsed%items(1)%count >= 8) ang = parsed%real_at(1, 8)
         if (allocated(model%structures)) st = model%structures
         n0 = st%nodes%n
         e0 = st%elements%n
         call structure_build(st, model%geometry, parsed%real_at(1, 1), parsed%real_at(1, 2), &
                              parsed%real_at(1, 3), parsed%real_at(1, 4), &
                              int(parsed%int_at(1, 5), ip), int(parsed%int_at(1, 6), ip), &
                              parsed%real_at(1, 7), ang, error)
         if (allocated(error)) return
         if (.not. allocated(model%structures)) allocate (model%structures)
         model%structures = st
         write (line, '(a,i0,a,i0,a,i0,a,i0,a)') 'STRUCTURE: ', model%structures%elements%n - e0, &
            ' elements, nodes ', n0 + 1, ' to ', model%structures%nodes%n, ', material ', &
            parsed%int_at(1, 6), ' (element and interface)'
         call out%line(trim(line))
      end associate
   end subroutine handle_structure

   !> PRINT STE (elements), STC (interfaces), LM (lumped masses): one table,
   !> its title, column header and row chosen by `name`.
   subroutine structure_print(model, name, out)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(output_t), intent(inout) :: out
      integer(ip) :: i, n
      character(len=240) :: line
      character(len=8) :: state
      if (.not. allocated(model%structures)) then
         call out%line('PRINT '//name//': there are no structural elements (give STRUCTURE)')
         return
      end if
      associate (st => model%structures, el => model%structures%elements, &
                 ifc => model%structures%interfaces, nd => model%structures%nodes)
         select case (name)
         case ('STE')
            call out%line('Structural elements (axial force tension +, thrust = -axial; '// &
                          'moments counter-clockwise on the element ends)')
            call out%line('    elem   node1   node2  mat     thickness        length'// &
                          '         axial         shear      moment 1      moment 2')
            n = el%n
         case ('STC')
            call out%line('Structural element interfaces (normal force compression +)')
            call out%line('   inter    node   block           x             y'// &
                          '       n-force       s-force        n-disp        s-disp  state')
            n = ifc%n
         case default
            call out%line('Structural element lumped masses')
            call out%line('    node           x             y        x-disp        y-disp'// &
                          '      rotation          mass       x-force       y-force')
            n = nd%n
         end select
         do i = 1, n
            select case (name)
            case ('STE')
               write (line, '(i8,2i8,i5,6(1x,a))') i, el%n1(i), el%n2(i), el%material(i), &
                  fmt_real(el%thick(i), 13, 5), fmt_real(el%length0(i), 13, 5), &
                  fmt_real(el%axial(i), 13, 5), fmt_real(el%shear(i), 13, 5), &
                  fmt_real(el%m1(i), 13, 5), fmt_real(el%m2(i), 13, 5)
            case ('STC')
               state = 'elastic'
               if (iand(ifc%flags(i), iface_slip) /= 0) state = 'slip'
               if (iand(ifc%flags(i), iface_broken) /= 0) state = 'broken'
               write (line, '(3i8,6(1x,a),2x,a)') i, ifc%node(i), ifc%block(i), &
                  fmt_real(ifc%x(i), 13, 5), fmt_real(ifc%y(i), 13, 5), fmt_real(ifc%fn(i), 13, 5), &
                  fmt_real(ifc%fs(i), 13, 5), fmt_real(ifc%un(i), 13, 5), &
                  fmt_real(ifc%us(i), 13, 5), trim(state)
            case default
               write (line, '(i8,8(1x,a))') i, fmt_real(nd%x(i), 13, 5), fmt_real(nd%y(i), 13, 5), &
                  fmt_real(nd%ux(i), 13, 5), fmt_real(nd%uy(i), 13, 5), fmt_real(nd%rot(i), 13, 5), &
                  fmt_real(nd%mass(i), 13, 5), fmt_real(nd%fx(i), 13, 5), fmt_real(nd%fy(i), 13, 5)
            end select
            call out%line(trim(line))
         end do
         if (name == 'STE' .and. el%n > 0) then
            write (line, '(a,a,a,a)') '   Young''s modulus of element 1: ', &
               trim(fmt_real(el%young(1), 12, 5)), ', area ', trim(fmt_real(el%area(1), 12, 5))
            call out%line(trim(line))
         end if
      end associate
   end subroutine structure_print

end module commands_structure
