!> REINFORCE and CABLE (UDEC manual (ICG1.5, 1989), Section 4.5) and PRINT
!> REINFORCE / PRINT CABLE: local reinforcement across joints and grouted
!> cables (src/structure/reinforce_*).
module commands_reinforce
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real, format_real
   use model_state, only: model_t
   use model_reinforcement, only: reinforcement_t, reinf_joint_normal
   use reinforce_generate, only: reinforce_build, cable_build
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, require_block
   implicit none
   private
   public :: handle_reinforcement, reinforce_print

contains

   !> REINFORCE mat x1 y1 x2 y2 (local reinforcement across the joints the
   !> segment crosses) or CABLE x1 y1 x2 y2 npoin mats asteel matg <preten>
   !> (a grouted cable). Both build on a copy of the model's reinforcement,
   !> which replaces it only when the command succeeds: a refused command
   !> changes nothing. A REINFORCE line that crosses no joint makes nothing
   !> and says so in a warning, and a batch run goes on: one bolt of a
   !> pattern that happens to lie in intact rock is no input error (local
   !> reinforcement acts across joints only, manual Section 3.10.1).
   subroutine handle_reinforcement(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(reinforcement_t) :: rf
      real(wp) :: pre
      integer(ip) :: made, n0, k, nfree
      character(len=200) :: line
      associate (model => ctx%model, out => ctx%out)
         call require_block(model, parsed%name, error)
         if (allocated(error)) return
         if (allocated(model%reinforcement)) rf = model%reinforcement
         n0 = rf%nodes%n
         if (parsed%name == 'REINFORCE') then
            call reinforce_build(rf, model%geometry, int(parsed%int_at(1, 1), ip), &
                                 parsed%real_at(1, 2), parsed%real_at(1, 3), parsed%real_at(1, 4), &
                                 parsed%real_at(1, 5), made, error)
         else
            pre = 0.0_wp
            if (parsed%items(1)%count >= 9) pre = parsed%real_at(1, 9)
            call cable_build(rf, model%geometry, parsed%real_at(1, 1), parsed%real_at(1, 2), &
                             parsed%real_at(1, 3), parsed%real_at(1, 4), &
                             int(parsed%int_at(1, 5), ip), int(parsed%int_at(1, 6), ip), &
                             parsed%real_at(1, 7), &
                             int(parsed%int_at(1, 8), ip), pre, error)
         end if
         if (allocated(error)) return
         if (parsed%name == 'REINFORCE' .and. made == 0) then
            call out%line('Warning: REINFORCE: the line ('//format_real(parsed%real_at(1, 2))// &
                          ', '//format_real(parsed%real_at(1, 3))//') - ('// &
                          format_real(parsed%real_at(1, 4))//', '// &
                          format_real(parsed%real_at(1, 5))//') crosses no joint between '// &
                          'two blocks: no element made (local reinforcement acts across joints '// &
                          'only, manual Section 3.10.1)')
            return
         end if
         if (.not. allocated(model%reinforcement)) allocate (model%reinforcement)
         model%reinforcement = rf
         if (parsed%name == 'REINFORCE') then
            write (line, '(a,i0,a,i0,a,i0)') 'REINFORCE: ', made, ' elements across joints, ', &
               rf%reinf%n - made + 1, ' to ', rf%reinf%n
         else
            nfree = 0
            do k = n0 + 1, rf%nodes%n
               if (rf%nodes%block(k) == 0) nfree = nfree + 1
            end do
            write (line, '(a,i0,a,i0,a,i0,a,i0,a)') 'CABLE ', rf%ncable, ': nodes ', n0 + 1, &
               ' to ', rf%nodes%n, ' (', nfree, ' in no block)'
         end if
         call out%line(trim(line))
      end associate
   end subroutine handle_reinforcement

   !> PRINT REINFORCE (local reinforcement) or PRINT CABLE (its nodes, then
   !> its elements).
   subroutine reinforce_print(model, name, out)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(output_t), intent(inout) :: out
      if (.not. allocated(model%reinforcement)) then
         call out%line('PRINT '//name//': there is no reinforcement (give REINFORCE or CABLE)')
         return
      end if
      if (name == 'REINFORCEMENT') then
         if (model%reinforcement%reinf%n == 0) then
            call out%line('PRINT REINFORCE: there are no local reinforcement elements')
         else
            call table('REINFORCEMENT')
         end if
      else if (model%reinforcement%nodes%n == 0) then
         call out%line('PRINT CABLE: there are no cables')
      else
         call table('NODES')
         call table('ELEMENTS')
      end if
   contains
      !> One table (REINFORCEMENT, NODES or ELEMENTS): its title, column
      !> header and a row per entry.
      subroutine table(which)
         character(len=*), intent(in) :: which
         integer(ip) :: i, n
         character(len=260) :: line
         character(len=6) :: host
         associate (r => model%reinforcement%reinf, nd => model%reinforcement%nodes, &
                    el => model%reinforcement%elements)
            select case (which)
            case ('REINFORCEMENT')
               call out%line('Local reinforcement (axial force tension +; joint forces on block 2: '// &
                             'shear along the joint, normal + pulls the blocks together)')
               call out%line('    elem  block1  block2  mat           x             y'// &
                             '   shear-disp   normal-disp        axial        shear'// &
                             '    joint-s-f    joint-n-f')
               n = r%n
            case ('NODES')
               call out%line('Cable nodes (slip along the cable; grout force on the steel)')
               call out%line('    node   cable   block    zone  host           x             y'// &
                             '         slip  grout-force')
               n = nd%n
            case default
               call out%line('Cable elements (axial force tension +)')
               call out%line('    elem   cable   node1   node2  mat         area       length'// &
                             '        axial')
               n = el%n
            end select
            do i = 1, n
               select case (which)
               case ('REINFORCEMENT')
                  write (line, '(3i8,i5,8(1x,a))') i, r%block1(i), r%block2(i), r%material(i), &
                     fmt_real(0.5_wp*(r%x1(i) + r%x2(i)), 13, 5), &
                     fmt_real(0.5_wp*(r%y1(i) + r%y2(i)), 13, 5), &
                     fmt_real(r%dx(i)*r%tx(i) + r%dy(i)*r%ty(i), 12, 4), &
                     fmt_real(opening(i), 12, 4), &
                     fmt_real(r%fa(i), 12, 4), fmt_real(r%fs(i), 12, 4), &
                     fmt_real(r%fjs(i), 12, 4), fmt_real(r%fjn(i), 12, 4)
               case ('NODES')
                  host = 'free'
                  if (nd%block(i) > 0) host = 'rigid'
                  if (nd%zone(i) > 0) host = 'zone'
                  write (line, '(4i8,2x,a5,4(1x,a))') i, nd%cable(i), nd%block(i), nd%zone(i), &
                     host, fmt_real(nd%x(i), 13, 5), fmt_real(nd%y(i), 13, 5), &
                     fmt_real(nd%slip(i), 12, 4), fmt_real(nd%fg(i), 12, 4)
               case default
                  write (line, '(4i8,i5,3(1x,a))') i, el%cable(i), el%n1(i), el%n2(i), el%mats(i), &
                     fmt_real(el%area(i), 12, 4), fmt_real(el%length(i), 12, 5), &
                     fmt_real(el%axial(i), 12, 5)
               end select
               call out%line(trim(line))
            end do
         end associate
      end subroutine table

      !> Normal displacement across the joint, opening positive (the normal
      !> from block 1 towards block 2).
      real(wp) function opening(i) result(u)
         integer(ip), intent(in) :: i
         real(wp) :: nx, ny
         associate (r => model%reinforcement%reinf)
            call reinf_joint_normal(r, i, nx, ny)
            u = r%dx(i)*nx + r%dy(i)*ny
         end associate
      end function opening
   end subroutine reinforce_print

end module commands_reinforce
