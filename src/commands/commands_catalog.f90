!> The registry of every command: each family module registers its own
!> commands (commands_context); this module only asks every family, orders the
!> table by name and builds the parser's grammar from it. A new command is
!> registered in its family module; a new family adds one call here.
module commands_catalog
   use core_error, only: error_t, set_error
   use commands_tokens, only: to_upper
   use commands_grammar, only: grammar_t, grammar_build_from => grammar_build
   use commands_context, only: registry_t, command_entry_t
   use commands_control, only: register_control_commands
   use commands_geometry, only: register_geometry_commands
   use commands_geometry_extras, only: register_geometry_extras_commands
   use commands_mechanics, only: register_mechanics_commands
   use commands_properties, only: register_property_commands
   use commands_print, only: register_print_commands
   use commands_io, only: register_io_commands
   use commands_boundary, only: register_boundary_commands
   use commands_be, only: register_be_commands
   use commands_plot, only: register_plot_commands
   use commands_zones, only: register_zone_commands
   use commands_structure, only: register_structure_commands
   use commands_fluid, only: register_fluid_commands
   use commands_thermal, only: register_thermal_commands
   use commands_zpress, only: register_zpress_commands
   use commands_export, only: register_export_commands
   implicit none
   private
   public :: catalog_build, grammar_build

contains

   !> Every family's commands, ordered by name, and the grammar the parser
   !> reads (command i of the grammar is entry i of the registry).
   subroutine catalog_build(registry, grammar, error)
      type(registry_t), intent(out) :: registry
      type(grammar_t), intent(out) :: grammar
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: defs(:)
      integer :: i, width
      call register_control_commands(registry)
      call register_geometry_commands(registry)
      call register_geometry_extras_commands(registry)
      call register_mechanics_commands(registry)
      call register_property_commands(registry)
      call register_print_commands(registry)
      call register_io_commands(registry)
      call register_boundary_commands(registry)
      call register_be_commands(registry)
      call register_plot_commands(registry)
      call register_zone_commands(registry)
      call register_structure_commands(registry)
      call register_fluid_commands(registry)
      call register_thermal_commands(registry)
      call register_zpress_commands(registry)
      call register_export_commands(registry)
      call join_set_keywords(registry, error)
      if (allocated(error)) return
      call sort_by_name(registry)
      width = 1
      do i = 1, registry%n
         associate (e => registry%entries(i))
            width = max(width, len(e%name) + len(e%positional) + len(e%loose) + &
                        len(e%keywords) + 3)
         end associate
      end do
      allocate (character(len=width) :: defs(registry%n))
      do i = 1, registry%n
         associate (e => registry%entries(i))
            if (i > 1) then
               if (to_upper(e%name) == to_upper(registry%entries(i - 1)%name)) then
                  call set_error(error, 'registry: command '//to_upper(e%name)// &
                                 ' is registered twice')
                  return
               end if
            end if
            defs(i) = e%name//'|'//e%positional//'|'//e%loose//'|'//e%keywords
         end associate
      end do
      call grammar_build_from(grammar, defs, error)
      if (allocated(error)) return
      call check_notes(registry, grammar, error)
   end subroutine catalog_build

   !> The parser's grammar alone (tests of the command language).
   subroutine grammar_build(grammar, error)
      type(grammar_t), intent(out) :: grammar
      type(error_t), allocatable, intent(out) :: error
      type(registry_t) :: registry
      call catalog_build(registry, grammar, error)
   end subroutine grammar_build

   !> SET's keywords, registered by the families (add_set), into SET's definition.
   subroutine join_set_keywords(registry, error)
      type(registry_t), intent(inout) :: registry
      type(error_t), allocatable, intent(out) :: error
      integer :: i, k
      k = registry%find('SET')
      if (k == 0) then
         call set_error(error, 'registry: SET keywords registered but no SET command')
         return
      end if
      associate (e => registry%entries(k))
         do i = 1, registry%nset
            if (len(e%keywords) > 0) e%keywords = e%keywords//';'
            e%keywords = e%keywords//registry%set_keywords(i)%keywords
         end do
         e%notes = [e%notes, registry%set_notes]
         e%nnotes = size(e%notes)
      end associate
   end subroutine join_set_keywords

   !> Every keyword note names a keyword of its command ('' = the positional
   !> arguments).
   subroutine check_notes(registry, grammar, error)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j, k
      logical :: found
      do i = 1, registry%n
         associate (e => registry%entries(i), c => grammar%commands(i))
            do j = 1, e%nnotes
               if (len(e%notes(j)%keyword) == 0) cycle
               found = .false.
               do k = 1, c%nkeywords
                  if (c%keywords(k)%name == e%notes(j)%keyword) found = .true.
               end do
               if (.not. found) then
                  call set_error(error, 'registry: note on '//e%notes(j)%keyword// &
                                 ', which is not a keyword of '//c%name)
                  return
               end if
            end do
         end associate
      end do
   end subroutine check_notes

   !> Insertion sort of the entries by upper-case name (about 70 of them).
   subroutine sort_by_name(registry)
      type(registry_t), intent(inout) :: registry
      type(command_entry_t) :: key
      integer :: i, j
      do i = 2, registry%n
         key = registry%entries(i)
         j = i - 1
         do while (j >= 1)
            if (to_upper(registry%entries(j)%name) <= to_upper(key%name)) exit
            registry%entries(j + 1) = registry%entries(j)
            j = j - 1
         end do
         registry%entries(j + 1) = key
      end do
   end subroutine sort_by_name

end module commands_catalog
