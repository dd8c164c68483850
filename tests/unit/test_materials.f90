!> The property table knows every PROPERTY keyword of the command table, and
!> stores values per material number.
program test_materials
   use core_kinds, only: wp
   use core_error, only: error_t
   use testing, only: check, check_close, testing_finish
   use model_materials, only: material_table_t, property_index, canonical_property
   use commands_grammar, only: grammar_t
   use commands_catalog, only: grammar_build
   implicit none
   type(grammar_t) :: g
   type(error_t), allocatable :: error
   type(material_table_t) :: t
   integer :: c, k

   call grammar_build(g, error)
   c = g%find_command('PROPERTY')
   do k = 1, g%commands(c)%nkeywords
      associate (name => g%commands(c)%keywords(k)%name)
         select case (name)
         case ('MATERIAL', 'JMATERIAL', 'COND')
         case default
            call check(property_index(canonical_property(name)) > 0, &
                       'PROPERTY keyword has a table slot: '//name)
         end select
      end associate
   end do
   call check(canonical_property('K') == 'BULK', 'K is BULK')
   call check(canonical_property('G') == 'SHEAR', 'G is SHEAR')

   call t%set(3, 'DENSITY', 2650.0_wp)
   call t%set(1, 'JKN', 1.0e10_wp)
   call check_close(t%get(3, 'DENSITY'), 2650.0_wp, 0.0_wp, 'density of material 3')
   call check_close(t%get(1, 'JKN'), 1.0e10_wp, 0.0_wp, 'JKN of material 1')
   call check_close(t%get(2, 'DENSITY'), 0.0_wp, 0.0_wp, 'unset property is zero')
   call check(t%is_given(3, 'DENSITY') .and. .not. t%is_given(1, 'DENSITY'), 'given flags')
   call check_close(t%get(99, 'DENSITY'), 0.0_wp, 0.0_wp, 'unknown material is zero')
   call testing_finish()
end program test_materials
