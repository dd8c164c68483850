!> Abbreviated keywords and sub-keywords against the manual's tables. The rule
!> (manual Section 4, 4.5, 4.6): the capitalised part of a keyword is its minimum
!> abbreviation; sub-keywords (PRINT CONTACT Disp Force State, PRINT ZONE STate
!> STRess, BOUNDARY XHistory Constant ..) follow the same rule within their own
!> table, so PRINT ZONE ST is ZONE STATE and PRINT CON D is CONTACT DISP. Each
!> case names the manual table it comes from. Exact comparisons (canonical names).
program test_abbreviations
   use core_error, only: error_t
   use testing, only: check, check_string, testing_finish
   use commands_tokens, only: token_t, tokenize
   use commands_grammar, only: grammar_t
   use commands_catalog, only: grammar_build
   use commands_parser, only: parsed_t, parse_command
   implicit none
   type(grammar_t) :: g
   type(error_t), allocatable :: error

   call grammar_build(g, error)
   call check(.not. allocated(error), 'grammar builds')
   if (allocated(error)) call testing_finish()

   ! --- PRINT (manual 4.5 PRint, sub-keyword tables of CONTACTS, ZONE, GRIDPOINT,
   ! BOUNDARY, PROPERTY)
   call expect('PRINT ZONE ST', 'ZONES STATE')            ! Zone: STate
   call expect('PRINT ZONE STR', 'ZONES STRESS')          ! Zone: STRess
   call expect('PRINT ZONE STATE STRESS', 'ZONES STATE STRESS')
   call expect('PRINT CON D', 'CONTACTS DISPLACEMENTS')   ! Contacts: Disp
   call expect('PRINT CON F S', 'CONTACTS FORCES STATE')  ! Contacts: Force, State
   call expect('PRINT C', 'CONTACTS')                     ! Contacts*
   call expect('PRINT GRID D F S T', 'GRIDPOINTS DISPLACEMENTS FORCES STATE TEMPERATURE')
   call expect('PRINT G S', 'GRIDPOINTS STATE')            ! Gridpoint: State
   call expect('PRINT BOUND S D', 'BOUNDARY STATE DISPLACEMENTS')
   call expect('PRINT BO FL FO T BE', 'BOUNDARY FLUID FORCES THERMAL BE')
   call expect('PRINT PROP B', 'PROPERTY BLOCKS')          ! Property: Block
   call expect('PRINT PROP C J', 'PROPERTY CONTACTS JOINT') ! Contact, Joint
   call expect('PRINT PROP BO CAB', 'PROPERTY BOUNDARY CABLE') ! BOundary, CABle
   call expect('PRINT PROP R S F', 'PROPERTY REINFORCEMENT STRUCTURAL FLUID')
   ! the context ends at a word of the main table
   call expect('PRINT CON D BLOCK', 'CONTACTS DISPLACEMENTS BLOCKS')
   call expect('PRINT CON STATUS', 'CONTACTS STATUS')
   call expect('PRINT ZONE STR MAX', 'ZONES STRESS MAXIMA')
   call expect('PRINT MAX CON', 'MAXIMA CONTACTS')
   call expect('PRINT H 1 2', 'HISTORY')                   ! History n1 ..
   call expect('PRINT HM 1', 'HMAX')                       ! HMax
   ! ambiguous in the sub-table (Fluid and Forces are both "F" in the manual)
   call expect_error('PRINT BOUND F', "PRINT BOUNDARY: ambiguous keyword 'F' (could be " &
                     //'FLUID, FORCES; type more letters)')

   ! --- BOUNDARY (manual 4.5, History Types: Constant, Linear, Sine, COsine, Function)
   call expect('BOUND XLOAD 1 XHIST C', 'XLOAD XHISTORY CONSTANT')
   call expect('BOUND YL 1 YH L', 'YLOAD YHISTORY LINEAR')
   call expect('BOUND STRESS 0 0 -1 H S 10 0.1', 'STRESS HISTORY SINE')
   call expect('BOUND XVEL 1 XH CO 10 0.1', 'XVEL XHISTORY COSINE')
   call expect('BOUND YVEL 1 YH F', 'YVEL YHISTORY FUNCTION')
   call expect('BOUND XF YF', 'XFREE YFREE')                ! XFree, YFree
   call expect('BOUND C 1 5 XVEL 0', 'CORNER XVEL')         ! Corner ic1 ic2, XVEL
   call expect('BOUND XV YV', 'XVISC YVISC')                ! XVisc, YVisc
   call expect('BOUND XM 2 YM 3', 'XMUL YMUL')              ! XMul, YMul
   call expect('BOUND XG 1 2 3 YG 1 2 3', 'XGRAD YGRAD')

   ! --- HISTORY (manual 4.5 HISTORY: Ncyc NDis NStr SDis SStr XDis YDis XVel YVel
   ! Type Unbal Damp)
   call expect('HIST N 5 ND 1 NS 1 SD 1 SS 1', &
               'NCYC NDISPLACEMENT NSTR SDISPLACEMENT SSTR')
   call expect('HIST XD 1 2 YD 1 2 XV 1 2 YV 1 2', &
               'XDISPLACEMENT YDISPLACEMENT XVEL YVEL')
   call expect('HIST U D T 1', 'UNBAL DAMP TYPE')
   call expect('HIST XDIS 1,2 YDIS 1,2', 'XDISPLACEMENT YDISPLACEMENT')

   ! --- CHANGE (manual 4.5 CHange: Cons, Mat, SDEF, JCons, JMat, INterface)
   call expect('CHANGE C 3 M 2', 'CONS MAT')
   call expect('CHANGE IN 1 2 JC 2 JM 1', 'INTERFACE JCONS JMAT')

   ! --- GENERATE (manual 4.5 GEnerate: Edge, Quad, Manual Gridpoint .. Zone ..)
   call expect('GEN E 2', 'EDGE')
   call expect('GEN Q 1 2', 'QUAD')
   call expect('GEN M G 5,15 0,20 0,10 Z 1,2,3', 'MANUAL GRIDPOINT ZONE')

   ! --- SET (manual 4.5 SEt: CSCAn CAPratio CLEmin DScan Edge Gravity JCondf JMatdf
   ! Log OVtol Ptol UPcon YWtable ZPress)
   call expect('SET CSCA 10 CAP 2 CLE 0.1 DS 3', 'CSCAN CAPRATIO CLEMIN DSCAN')
   call expect('SET G 0 -10 JC 2 JM 1 OV 0.1', 'GRAVITY JCONDF JMATDF OVTOL')
   call expect('SET P 0.01 UP 1 YW 5', 'PTOL UPCON YWTABLE')
   call expect('SET L ON', 'LOG ON')

   ! --- PROPERTY (manual 4.5: Density, K, G, SHear, Bulk, Friction, Cohesion, JKN ..)
   call expect('PROP M 1 D 2000 B 1e9 SH 1e9', 'MATERIAL DENSITY BULK SHEAR')
   call expect('PROP JM 1 JKN 1 JKS 1 JF 0.5 JC 1 JT 1', &
               'JMATERIAL JKN JKS JFRIC JCOH JTENSILE')

   ! --- DAMPING and PLOT (manual 4.5 Damping; 4.6 PLot keywords)
   call expect('DAMP A', 'AUTO')
   call expect('PLOT BL ZO', 'BLOCKS ZONES')               ! BLocks, ZOnes
   call expect('PLOT D DS DO', 'DISPLACEMENTS DSH DOMAINS') ! Disp, DSh
   call expect('PLOT CA CO CF CL', 'CABLE CONTACTS CFORCE CLOSURE')
   call expect('PLOT VE VF HO', 'VELOCITY VFLOW HOEK')      ! Vel, Vflow, Hoek
   call expect('PRINT ST', 'STATUS')                       ! PRint STatus
   call expect('PRINT D DL R RI T 1', 'DOMAINS DLIST REINFORCEMENT RIGID TABLE')
   call expect('PRINT M MA 1', 'MAXIMA MAT')               ! Maxima, MAt
   call expect('PRINT FL FLU FO', 'FLOWS FLUID FORCES')     ! Flows*
   call expect('PRINT FI x.txt H', 'FILE HISTORY')          ! File filename
   call expect_error('PRINT F', "PRINT: ambiguous keyword 'F' (could be FILE, FLOWS;")
   call expect('PLOT XRev AB 1 HI 2 3', 'XREV AB HISTORY')

   ! ambiguous abbreviations name the candidates
   call expect_error('PLOT H 1', "PLOT: ambiguous keyword 'H' (could be HISTORY, HOEK; " &
                     //'type more letters)')
   call expect_error('PLOT C', "PLOT: ambiguous keyword 'C' (could be CABLE, CONTACTS;")
   call expect_error('PLOT V', "PLOT: ambiguous keyword 'V' (could be VELOCITY, VFLOW;")

   call testing_finish()

contains

   !> Parse `line` and compare the canonical names of its keyword items.
   subroutine expect(line, names)
      character(len=*), intent(in) :: line, names
      type(parsed_t) :: p
      type(token_t), allocatable :: tokens(:)
      type(error_t), allocatable :: err
      integer :: n, k
      character(len=:), allocatable :: got
      call tokenize(line, tokens, n)
      call parse_command(g, line, tokens, n, p, err)
      if (allocated(err)) then
         call check(.false., line//' parses ('//err%message//')')
         return
      end if
      got = ''
      do k = 1, p%nitems
         if (p%items(k)%keyword <= 0) cycle
         if (len(got) > 0) got = got//' '
         got = got//p%items(k)%name
      end do
      call check_string(got, names, line)
   end subroutine expect

   subroutine expect_error(line, message)
      character(len=*), intent(in) :: line, message
      type(parsed_t) :: p
      type(token_t), allocatable :: tokens(:)
      type(error_t), allocatable :: err
      integer :: n
      call tokenize(line, tokens, n)
      call parse_command(g, line, tokens, n, p, err)
      call check(allocated(err), line//' is refused')
      if (allocated(err)) call check(index(err%message, message) == 1, &
                                     line//': message "'//err%message//'"')
   end subroutine expect_error

end program test_abbreviations
