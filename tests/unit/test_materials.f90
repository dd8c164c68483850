!> The property table knows every PROPERTY keyword of the command table, and
!> stores values per material number. The declarations are in id order (the
!> restart files' row order), PROPERTY's keywords come from them, and PROPERTY
!> refuses misspelt names (naming the close ones) and out-of-range values
!> without changing the model.
program test_materials
   use core_kinds, only: wp
   use core_error, only: error_t
   use testing, only: check, check_close, testing_finish
   use model_materials, only: material_table_t
   use model_properties, only: prop_density, prop_jkn, prop_bulk, prop_xcond, prop_ycond, &
                               property_index, canonical_property, property_table, &
                               nproperties
   use commands_grammar, only: grammar_t
   use commands_catalog, only: grammar_build
   use commands_session, only: session_t
   use testing_session, only: session_new_quiet, session_run, lines_contain
   implicit none
   type(grammar_t) :: g
   type(error_t), allocatable :: error
   type(material_table_t) :: t
   type(session_t) :: s
   character(len=200), allocatable :: lines(:)
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

   call t%set(3, prop_density, 2650.0_wp)
   call t%set(1, prop_jkn, 1.0e10_wp)
   call check_close(t%get(3, prop_density), 2650.0_wp, 0.0_wp, 'density of material 3')
   call check_close(t%get(1, prop_jkn), 1.0e10_wp, 0.0_wp, 'JKN of material 1')
   call check_close(t%get(2, prop_density), 0.0_wp, 0.0_wp, 'unset property is zero')
   call check(t%is_given(3, prop_density) .and. .not. t%is_given(1, prop_density), 'given flags')
   call check_close(t%get(99, prop_density), 0.0_wp, 0.0_wp, 'unknown material is zero')

   do k = 1, nproperties
      call check(property_table(k)%id == k, 'declaration in id order: '//property_table(k)%name)
      call check(property_index(property_table(k)%name) == k, &
                 'name finds its id: '//property_table(k)%name)
   end do
   call check(nproperties == 45, 'the 45 rows of /materials/value (schema 1 on)')

   ! PROPERTY against the declarations: aliases, abbreviations, misspellings, ranges
   call session_new_quiet(s)
   call session_run(s, 'PROP MAT 1 DENS 2000 K 1e9 COND 3', lines)
   call check(s%nerrors == 0, 'PROP with an alias and an abbreviation is accepted')
   call check_close(s%model%materials%get(1, prop_density), 2000.0_wp, 0.0_wp, 'DENS is DENSITY')
   call check_close(s%model%materials%get(1, prop_bulk), 1.0e9_wp, 0.0_wp, 'K is BULK')
   call check(s%model%materials%get(1, prop_xcond) == 3.0_wp .and. &
              s%model%materials%get(1, prop_ycond) == 3.0_wp, 'COND sets XCOND and YCOND')
   call session_run(s, 'PROP MAT 1 DENS 3000 JKX 1e9', lines)
   call check(s%nerrors == 1, 'a misspelt property name is an error')
   call check(lines_contain(lines, "PROPERTY: unknown keyword 'JKX' (closest: JKN, JKS"), &
              'the error names the close declared names')
   call session_run(s, 'PROP MAT 1 DENS 3000 COHESIN 1e6', lines)
   call check(lines_contain(lines, 'closest: COHESION'), 'COHESIN is close to COHESION')
   call session_run(s, 'PROP JMAT 1 DENS 3000 JKN -1e9', lines)
   call check(s%nerrors == 3, 'a negative stiffness is an error')
   call check(lines_contain(lines, "PROPERTY JKN: expected a real number >= 0, got '-1e9'"), &
              'the error names command, token and expectation')
   call session_run(s, 'PROP MAT 1 DENS -3000', lines)
   call check(s%nerrors == 4, 'a negative density is an error')
   call check_close(s%model%materials%get(1, prop_density), 2000.0_wp, 0.0_wp, &
                    'rejected PROPERTY commands changed nothing')
   call check(.not. s%model%materials%is_given(1, prop_jkn), 'no JKN stored by a rejected line')
   call testing_finish()
end program test_materials
