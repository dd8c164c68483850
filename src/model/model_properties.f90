!> The material properties the physics read (manual Section 4.5, PROPERTY),
!> declared once: one table per physics, each entry with its named id, the
!> manual's keyword (capitalised prefix = minimum abbreviation, as in the
!> command tables), units, default and valid range. The ids index the typed
!> array `material_table_t%value(id, mat)`; they follow the order of the
!> restart files' /materials/value rows (schema 1 onwards), so the tables must
!> keep that order (test_materials checks id == position).
!>
!> Cycle, law and output code reads `materials%get(mat, prop_jkn)`; names are
!> looked up only here, by PROPERTY and by PRINT PROPERTY.
module model_properties
   use core_kinds, only: wp
   use core_strings, only: to_upper
   implicit none
   private
   public :: property_def_t, property_alias_t, property_table, property_aliases
   public :: nproperties, property_names, property_index, canonical_property
   public :: property_keyword_spec, joint_material_property

   integer, parameter :: name_len = 10

   !> One declared property. `nonnegative` is the valid range (values >= 0;
   !> otherwise any real); the parser refuses anything else before PROPERTY
   !> changes the model. Units are UDEC's consistent units (Section 4.5).
   type :: property_def_t
      integer :: id = 0
      character(len=name_len) :: name = ''      !< canonical stored name
      character(len=name_len) :: keyword = ''   !< manual spelling: CCohesion
      character(len=16) :: unit = ''
      real(wp) :: default = 0.0_wp              !< value when never given (UDEC: 0)
      logical :: nonnegative = .true.
      character(len=40) :: meaning = ''
   end type property_def_t

   !> A keyword that sets declared properties under another name: K, G, COND.
   type :: property_alias_t
      character(len=name_len) :: keyword = ''   !< manual spelling
      integer :: first = 0, last = 0            !< ids set (COND: XCOND..YCOND)
   end type property_alias_t

   ! ---- contact-point joints (JCONS 1, Section 4.5 "contact" properties) -----
   integer, parameter, public :: prop_kn = 1, prop_ks = 2, prop_ccohesion = 3, &
      prop_cperm = 4, prop_cdilation = 5, prop_cfriction = 6, prop_ctensile = 7
   type(property_def_t), parameter :: point_contact_properties(*) = [ &
      property_def_t(prop_kn, 'KN', 'KN', 'force/length', 0.0_wp, .true., &
                     'contact normal stiffness'), &
      property_def_t(prop_ks, 'KS', 'KS', 'force/length', 0.0_wp, .true., &
                     'contact shear stiffness'), &
      property_def_t(prop_ccohesion, 'CCOHESION', 'CCohesion', 'force', 0.0_wp, .true., &
                     'contact cohesion'), &
      property_def_t(prop_cperm, 'CPERM', 'CPerm', '1/(stress time)', 0.0_wp, .true., &
                     'contact permeability factor'), &
      property_def_t(prop_cdilation, 'CDILATION', 'CDilation', 'tan(angle)', 0.0_wp, .true., &
                     'contact dilation coefficient (tangent of the angle)'), &
      property_def_t(prop_cfriction, 'CFRICTION', 'CFriction', 'tan(angle)', 0.0_wp, .true., &
                     'contact friction coefficient (tangent of the angle)'), &
      property_def_t(prop_ctensile, 'CTENSILE', 'CTensile', 'force', 0.0_wp, .true., &
                     'contact tensile strength')]

   ! ---- joint flow apertures (Section 7.3) -----------------------------------
   integer, parameter, public :: prop_azero = 8, prop_ares = 9
   type(property_def_t), parameter :: fluid_properties(*) = [ &
      property_def_t(prop_azero, 'AZERO', 'AZero', 'length', 0.0_wp, .false., &
                     'aperture at zero normal stress'), &
      property_def_t(prop_ares, 'ARES', 'ARes', 'length', 0.0_wp, .true., &
                     'residual aperture')]

   ! ---- joints with area contact (JCONS 1, 2, 3, 5) ----------------------------
   integer, parameter, public :: prop_jkn = 10, prop_jks = 11, prop_jcoh = 12, &
      prop_jdil = 13, prop_jfric = 14, prop_jperm = 15, prop_jtensile = 16, &
      prop_jen = 17, prop_jes = 18, prop_jif = 19, prop_jr = 20
   type(property_def_t), parameter :: joint_properties(*) = [ &
      property_def_t(prop_jkn, 'JKN', 'JKN', 'stress/length', 0.0_wp, .true., &
                     'joint normal stiffness'), &
      property_def_t(prop_jks, 'JKS', 'JKS', 'stress/length', 0.0_wp, .true., &
                     'joint shear stiffness'), &
      property_def_t(prop_jcoh, 'JCOH', 'JCoh', 'stress', 0.0_wp, .true., &
                     'joint cohesion'), &
      property_def_t(prop_jdil, 'JDIL', 'JDil', 'tan(angle)', 0.0_wp, .true., &
                     'joint dilation coefficient (tangent of the angle)'), &
      property_def_t(prop_jfric, 'JFRIC', 'JFric', 'tan(angle)', 0.0_wp, .true., &
                     'joint friction coefficient (tangent of the angle)'), &
      property_def_t(prop_jperm, 'JPERM', 'JPerm', '1/(stress time)', 0.0_wp, .true., &
                     'joint permeability factor'), &
      property_def_t(prop_jtensile, 'JTENSILE', 'JTensile', 'stress', 0.0_wp, .true., &
                     'joint tensile strength'), &
      property_def_t(prop_jen, 'JEN', 'JEN', '-', 0.0_wp, .false., &
                     'normal stiffness exponent (JCONS 3)'), &
      property_def_t(prop_jes, 'JES', 'JES', '-', 0.0_wp, .false., &
                     'shear stiffness exponent (JCONS 3)'), &
      property_def_t(prop_jif, 'JIF', 'JIF', 'radians', 0.0_wp, .true., &
                     'initial friction angle (JCONS 3)'), &
      property_def_t(prop_jr, 'JR', 'JR', '-', 0.0_wp, .true., &
                     'joint roughness (JCONS 3)')]

   ! ---- blocks and zones (rigid density; CONS 0, 1, 3, 4; Section 4.5) --------
   integer, parameter, public :: prop_bulk = 21, prop_shear = 22, prop_density = 23, &
      prop_cohesion = 24, prop_friction = 25, prop_tensile = 26, prop_dilation = 27, &
      prop_tf = 28, prop_hbs = 29, prop_hbm = 30, prop_ucs = 31, prop_ycomp = 32, &
      prop_yield = 33
   type(property_def_t), parameter :: zone_properties(*) = [ &
      property_def_t(prop_bulk, 'BULK', 'Bulk', 'stress', 0.0_wp, .true., &
                     'bulk modulus'), &
      property_def_t(prop_shear, 'SHEAR', 'SHear', 'stress', 0.0_wp, .true., &
                     'shear modulus'), &
      property_def_t(prop_density, 'DENSITY', 'Density', 'mass/volume', 0.0_wp, .true., &
                     'mass density'), &
      property_def_t(prop_cohesion, 'COHESION', 'Cohesion', 'stress', 0.0_wp, .true., &
                     'cohesion (CONS 3)'), &
      property_def_t(prop_friction, 'FRICTION', 'Friction', 'tan(angle)', 0.0_wp, .true., &
                     'friction coefficient, tangent of the angle (CONS 3)'), &
      property_def_t(prop_tensile, 'TENSILE', 'Tensile', 'stress', 0.0_wp, .true., &
                     'tensile strength (CONS 3)'), &
      property_def_t(prop_dilation, 'DILATION', 'DIlation', 'tan(angle)', 0.0_wp, .true., &
                     'dilation coefficient, tangent of the angle (CONS 3)'), &
      property_def_t(prop_tf, 'TF', 'TF', 'stress', 0.0_wp, .true., &
                     'tension cut-off (CONS 4)'), &
      property_def_t(prop_hbs, 'HBS', 'HBS', '-', 0.0_wp, .true., &
                     'Hoek-Brown s (CONS 4)'), &
      property_def_t(prop_hbm, 'HBM', 'HBM', '-', 0.0_wp, .true., &
                     'Hoek-Brown m (CONS 4)'), &
      property_def_t(prop_ucs, 'UCS', 'Ucs', 'stress', 0.0_wp, .true., &
                     'uniaxial compressive strength (CONS 4)'), &
      property_def_t(prop_ycomp, 'YCOMP', 'YComp', 'force', 0.0_wp, .true., &
                     'structural compressive yield'), &
      property_def_t(prop_yield, 'YIELD', 'Yield', 'force', 0.0_wp, .true., &
                     'structural tensile yield')]

   ! ---- local reinforcement (Section 7.2) ------------------------------------
   integer, parameter, public :: prop_rastiff = 34, prop_rsstiff = 35, prop_rlength = 36, &
      prop_ruaxial = 37, prop_rushear = 38, prop_rrfac = 39, prop_rsexp = 40, &
      prop_raexp = 41
   type(property_def_t), parameter :: reinforcement_properties(*) = [ &
      property_def_t(prop_rastiff, 'RASTIFF', 'RAStiff', 'force/length', 0.0_wp, .true., &
                     'axial stiffness'), &
      property_def_t(prop_rsstiff, 'RSSTIFF', 'RSStiff', 'force/length', 0.0_wp, .true., &
                     'shear stiffness'), &
      property_def_t(prop_rlength, 'RLENGTH', 'RLength', 'length', 0.0_wp, .true., &
                     'active length'), &
      property_def_t(prop_ruaxial, 'RUAXIAL', 'RUAXial', 'force', 0.0_wp, .true., &
                     'ultimate axial force'), &
      property_def_t(prop_rushear, 'RUSHEAR', 'RUShear', 'force', 0.0_wp, .true., &
                     'ultimate shear force'), &
      property_def_t(prop_rrfac, 'RRFAC', 'RRFac', '-', 0.0_wp, .true., &
                     'residual strength factor'), &
      property_def_t(prop_rsexp, 'RSEXP', 'RSExp', '-', 0.0_wp, .true., &
                     'shear softening exponent'), &
      property_def_t(prop_raexp, 'RAEXP', 'RAExp', '-', 0.0_wp, .true., &
                     'axial softening exponent')]

   ! ---- heat conduction (Section 7.4) ----------------------------------------
   integer, parameter, public :: prop_specheat = 42, prop_thexp = 43, prop_xcond = 44, &
      prop_ycond = 45
   type(property_def_t), parameter :: thermal_properties(*) = [ &
      property_def_t(prop_specheat, 'SPECHEAT', 'SPecheat', 'energy/(mass K)', 0.0_wp, &
                     .true., 'specific heat'), &
      property_def_t(prop_thexp, 'THEXP', 'THEXP', '1/K', 0.0_wp, .true., &
                     'linear thermal expansion'), &
      property_def_t(prop_xcond, 'XCOND', 'XCOnd', 'power/(length K)', 0.0_wp, .true., &
                     'x conductivity'), &
      property_def_t(prop_ycond, 'YCOND', 'YCOnd', 'power/(length K)', 0.0_wp, .true., &
                     'y conductivity')]

   !> Every declared property, in id order.
   type(property_def_t), parameter :: property_table(*) = [point_contact_properties, &
      fluid_properties, joint_properties, zone_properties, reinforcement_properties, &
      thermal_properties]
   integer, parameter :: nproperties = size(property_table)
   character(len=name_len), parameter :: property_names(nproperties) = property_table%name

   !> K and G are BULK and SHEAR; COND sets XCOND and YCOND (Section 7.4.2).
   type(property_alias_t), parameter :: property_aliases(*) = [ &
      property_alias_t('K', prop_bulk, prop_bulk), &
      property_alias_t('G', prop_shear, prop_shear), &
      property_alias_t('CONd', prop_xcond, prop_ycond)]

contains

   !> Canonical stored name of a PROPERTY keyword (K -> BULK, G -> SHEAR).
   !> COND is not one property: see property_aliases.
   pure function canonical_property(keyword) result(name)
      character(len=*), intent(in) :: keyword
      character(len=name_len) :: name
      select case (keyword)
      case ('K'); name = 'BULK'
      case ('G'); name = 'SHEAR'
      case default; name = keyword(1:min(name_len, len(keyword)))
      end select
   end function canonical_property

   !> Id of a canonical property name, 0 if unknown.
   pure integer function property_index(name) result(k)
      character(len=*), intent(in) :: name
      do k = 1, nproperties
         if (property_names(k) == name) return
      end do
      k = 0
   end function property_index

   !> Whether a PROPERTY keyword (canonical name or alias) belongs to a joint
   !> material (JMAT n: the contact-point, aperture and joint tables of
   !> Section 4.5, "Joint Material Properties"); the others are block, cable,
   !> reinforcement, structure and heat properties, given to MAT n.
   pure logical function joint_material_property(name) result(joint)
      character(len=*), intent(in) :: name
      integer :: k, a
      joint = .false.
      k = property_index(canonical_property(name))
      if (k == 0) then
         do a = 1, size(property_aliases)
            if (to_upper(property_aliases(a)%keyword) == name) k = property_aliases(a)%first
         end do
      end if
      if (k == 0) return
      joint = any(property_table(k)%id == point_contact_properties%id) .or. &
              any(property_table(k)%id == fluid_properties%id) .or. &
              any(property_table(k)%id == joint_properties%id)
   end function joint_material_property

   !> The keyword part of PROPERTY's command table, generated from the
   !> declarations: MAT/JMAT, then each property with its aliases, with the
   !> argument letter of its range (n: real >= 0, r: any real).
   function property_keyword_spec() result(spec)
      character(len=:), allocatable :: spec
      integer :: k, a
      spec = 'Material q;JMaterial q'
      do k = 1, nproperties
         spec = spec//';'//entry(property_table(k)%keyword, property_table(k)%nonnegative)
         do a = 1, size(property_aliases)
            if (property_aliases(a)%last /= k) cycle
            spec = spec//';'//entry(property_aliases(a)%keyword, &
                                    property_table(property_aliases(a)%first)%nonnegative)
         end do
      end do
   contains
      function entry(keyword, nonnegative) result(text)
         character(len=*), intent(in) :: keyword
         logical, intent(in) :: nonnegative
         character(len=:), allocatable :: text
         text = trim(keyword)//' '//merge('n', 'r', nonnegative)
      end function entry
   end function property_keyword_spec

end module model_properties
