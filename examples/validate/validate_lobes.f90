!> doc/validation.md §6.5: the two-lobe positions of data/exact (Y_WS = 5.0 and 5.3 mm), where
!> CONTACT's one contact patch holds a tread lobe and a flange-side lobe and we find two patches.
!> Under CONTACT's vertical load, each of our patches against the lobe nearest it (track y of the
!> lobe's pressure centre): the normal force with the strips of each patch on their own
!> (`local-hertz`) and with the patches coupled through the half-space (`coupled`, the default).
module validate_lobes
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp, error_type, fatal_error, material_type, prepared_profiles_type, &
      patch_geometry_type, normal_patch_type, find_contact_patches, wheelset_position_type, &
      normal_options_type, new_normal_options, normal_contact_type, prepare_normal_contact, &
      solve_vertical_load
   use validate_case, only: reference_material
   use validate_csv, only: csv_table_type, read_csv, column, summary_value, csv_writer_type
   use validate_tangential, only: case_set_type, solve_set, error_stats_type, error_stats
   use shcontact, only: tangential_options_type, parse_bound, parse_spin_model
   use shcontact_tangential_options, only: parse_spin_flexibility, parse_correction
   use validate_sets, only: pool_errors, set_all_positions, set_two_lobe
   implicit none
   private

   public :: run_lobes

   !> The two-lobe positions (data/exact/<name>/ with lobes.csv).
   character(len=*), parameter :: lobe_positions(2) = [character(len=7) :: 'yws5p0', 'yws5p3']
   character(len=*), parameter :: extra_root = 'data/exact/'

contains

   !> Every two-lobe position: lobes.csv and lobes.md in out_dir.
   subroutine run_lobes(prepared, out_dir, error)
      !> The prepared Manchester profiles (validate_case%load_manchester).
      type(prepared_profiles_type), intent(in) :: prepared
      !> Output directory (with a trailing '/').
      character(len=*), intent(in) :: out_dir
      !> Set when a file cannot be read or written, or a solve fails.
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      character(len=*), parameter :: reductions(2) = [character(len=11) :: 'local-hertz', &
         'coupled']
      type(csv_table_type) :: summary, lobes
      real(wp), allocatable :: y_lobe(:), n_lobe(:), y_ours(:), n_ours(:, :)
      real(wp) :: y_ws, f_z
      character(len=1024) :: md, msg
      integer :: ip, il, ir, unit, stat

      call out%open(out_dir//'lobes.csv', 'position,y_ws_mm,fz_N,lobe,contact_y_track_mm,'// &
         'contact_fn_N,ours_y_track_mm,fn_local_hertz_N,fn_coupled_N', error)
      if (allocated(error)) return
      open (newunit=unit, file=out_dir//'lobes.md', status='replace', action='write', &
         iostat=stat, iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, out_dir//'lobes.md: cannot write ('//trim(msg)//')')
         return
      end if
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release` (lobes.csv) -->', '', 'F_n in kN (share of the position''s total in %)', '', &
         '| position | lobe (CONTACT track y, mm) | CONTACT | our patch (track y, mm) | '// &
         '`local-hertz` | `coupled` |', '|---|---|---|---|---|---|'
      do ip = 1, size(lobe_positions)
         call read_csv(extra_root//trim(lobe_positions(ip))//'/summary.csv', summary, error)
         if (.not. allocated(error)) call summary_value(summary, 'y_ws', y_ws, error)
         if (.not. allocated(error)) call summary_value(summary, 'fz_vertical_input', f_z, error)
         if (.not. allocated(error)) call read_csv(extra_root//trim(lobe_positions(ip))// &
            '/lobes.csv', lobes, error)
         if (.not. allocated(error)) call column(lobes, 'ytr_cg', y_lobe, error)
         if (.not. allocated(error)) call column(lobes, 'Fn', n_lobe, error)
         if (allocated(error)) return
         if (allocated(y_ours)) deallocate (y_ours, n_ours)
         allocate (y_ours(size(y_lobe)), n_ours(size(y_lobe), size(reductions)))
         do ir = 1, size(reductions)
            call nearest_patch_loads(prepared, y_ws, f_z, reductions(ir), y_lobe, y_ours, &
               n_ours(:, ir), error)
            if (allocated(error)) return
         end do
         do il = 1, size(y_lobe)
            call out%row([y_ws, f_z, real(il, wp), y_lobe(il), n_lobe(il), y_ours(il), &
               n_ours(il, 1), n_ours(il, 2)], text=[character(len=8) :: lobe_positions(ip)], &
               digits=6)
            write (md, '(a,f4.1,a,i0,a,f7.2,a,f6.2,a,f5.1,a,f7.2,a,2(f6.2,a,f5.1,a))') &
               '| Y_WS = ', y_ws, ' mm | ', il, ' (', y_lobe(il), ') | ', &
               1.0e-3_wp*n_lobe(il), ' (', 100.0_wp*n_lobe(il)/sum(n_lobe), ') | ', y_ours(il), &
               ' | ', 1.0e-3_wp*n_ours(il, 1), ' (', 100.0_wp*n_ours(il, 1)/sum(n_ours(:, 1)), &
               ') | ', 1.0e-3_wp*n_ours(il, 2), ' (', 100.0_wp*n_ours(il, 2)/sum(n_ours(:, 2)), &
               ') |'
            write (unit, '(a)') trim(md)
         end do
      end do
      ! The DOE per lobe: each of our patches with the creepages carried to its point.
      write (unit, '(a)') '', 'DOE per lobe (defaults; creepages carried from CONTACT''s '// &
         'geometric point to each patch''s by the rigid slip): max \|Δf_x\| / max '// &
         '\|Δf_y\| ; P80 \|Δf_x\| / P80 \|Δf_y\|. Last two columns: against CONTACT''s '// &
         'joined patch (its one f for both lobes), the wheel''s Σ F/(μ Σ F_n) over our patches '// &
         '(tangential forces added as they are, each in its own plane) and the most loaded '// &
         'patch''s own f', '', '| position | lobe 1 (flange side) | lobe 2 (tread) | '// &
         'wheel Σ vs joined | most loaded vs joined |', '|---|---|---|---|---|'
      do ip = 1, size(lobe_positions)
         call lobe_doe(prepared, lobe_positions(ip), md, error)
         if (allocated(error)) return
         write (unit, '(a)') trim(md)
      end do
      close (unit)
      call out%close()
      write (output_unit, '(a)') 'shcontact-validate: two-lobe positions written to '// &
         out_dir//'lobes.csv, lobes.md'
   end subroutine run_lobes

   !> The 6³ DOE of one two-lobe position split by lobe (CONTACT's per-lobe forces, each over its
   !> lobe's F_n): each of our patches (default options, vertical load giving Σ F_n ≈ 64.7 kN as
   !> CONTACT's module 3) with ν_x,k = ξ − φ (y_k − y_G), ν_y,k = η, φ_k = φ, y_k the local y of
   !> the patch's reference point, (y_track,k − y_ref)/cos δ. One Markdown row.
   subroutine lobe_doe(prepared, name, row, error)
      type(prepared_profiles_type), intent(in) :: prepared
      character(len=*), intent(in) :: name
      character(len=*), intent(out) :: row
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: summary, lobes, doe
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(tangential_options_type) :: tangential
      type(case_set_type) :: set
      type(error_stats_type) :: ex, ey
      real(wp), allocatable :: y_lobe(:), nux(:), nuy(:), phi(:), lobe(:), fx(:), fy(:), &
         gx(:), gy(:)
      real(wp), allocatable :: jx(:), jy(:), wx(:), wy(:), mx(:), my(:)
      real(wp) :: y_ws, f_z, y_ref, delta, y_geo, y_k, n_main
      character(len=64) :: cell
      integer :: il, best, it
      logical, allocatable :: mine(:)
      type(csv_table_type) :: joined

      call read_csv(extra_root//trim(name)//'/summary.csv', summary, error)
      if (.not. allocated(error)) call summary_value(summary, 'y_ws', y_ws, error)
      if (.not. allocated(error)) call summary_value(summary, 'ycp_tr', y_ref, error)
      if (.not. allocated(error)) call summary_value(summary, 'delt', delta, error)
      if (.not. allocated(error)) call summary_value(summary, 'y_geo', y_geo, error)
      if (.not. allocated(error)) call read_csv(extra_root//trim(name)//'/lobes.csv', lobes, &
         error)
      if (.not. allocated(error)) call column(lobes, 'ytr_cg', y_lobe, error)
      if (.not. allocated(error)) call read_csv(extra_root//trim(name)// &
         '/doe_6x6x6_exact_nonhertz_per_lobe.csv', doe, error)
      if (.not. allocated(error)) call column(doe, 'nux', nux, error)
      if (.not. allocated(error)) call column(doe, 'nuy', nuy, error)
      if (.not. allocated(error)) call column(doe, 'phi_1_per_m', phi, error)
      if (.not. allocated(error)) call column(doe, 'lobe', lobe, error)
      if (.not. allocated(error)) call column(doe, 'fx', fx, error)
      if (.not. allocated(error)) call column(doe, 'fy', fy, error)
      if (.not. allocated(error)) call read_csv(extra_root//trim(name)// &
         '/doe_6x6x6_exact_nonhertz.csv', joined, error)
      if (.not. allocated(error)) call column(joined, 'fx', jx, error)
      if (.not. allocated(error)) call column(joined, 'fy', jy, error)
      if (allocated(error)) return
      allocate (wx(size(jx)), wy(size(jx)), mx(size(jx)), my(size(jx)))
      wx = 0.0_wp
      wy = 0.0_wp
      n_main = 0.0_wp
      ! The vertical load for which our normal forces add up to CONTACT's 64.7 kN.
      f_z = 64700.0_wp
      do it = 1, 4
         call wheel_patches(prepared, y_ws, f_z, 'coupled', geometry, patches, error)
         if (allocated(error)) return
         if (it < 4) f_z = f_z*64700.0_wp/sum(patches%load)
      end do
      call parse_bound('weighted', tangential%bound, error)
      if (.not. allocated(error)) call parse_spin_model('uniform', tangential%spin_model, error)
      if (.not. allocated(error)) call parse_spin_flexibility('longitudinal', &
         tangential%spin_flexibility, error)
      if (allocated(error)) return
      tangential%fields = .false.
      row = '| Y_WS = '//trim(adjustl(real_text(y_ws)))//' mm |'
      do il = 1, size(y_lobe)
         best = nearest(geometry, y_lobe(il))
         y_k = (geometry(best)%y_track - y_ref)/cos(delta)
         mine = nint(lobe) == il
         set%name = name
         set%phi = 1.0e-3_wp*pack(phi, mine)
         set%nux = pack(nux, mine) - set%phi*(y_k - y_geo)
         set%nuy = pack(nuy, mine)
         set%fx = pack(fx, mine)
         set%fy = pack(fy, mine)
         call solve_set(patches(best), reference_material(), tangential, set, gx, gy, error)
         if (allocated(error)) return
         ex = error_stats(abs(gx - set%fx))
         ey = error_stats(abs(gy - set%fy))
         write (cell, '(f5.3,a,f5.3,a,f5.3,a,f5.3)') ex%max, ' / ', ey%max, ' ; ', ex%p80, &
            ' / ', ey%p80
         row = trim(row)//' '//trim(cell)//' |'
         ! The lobe files hold the joined DOE's cases in its order, one row per lobe.
         wx = wx + patches(best)%load*gx/sum(patches%load)
         wy = wy + patches(best)%load*gy/sum(patches%load)
         if (patches(best)%load > n_main) then
            n_main = patches(best)%load
            mx = gx
            my = gy
         end if
      end do
      call add_cell(wx, wy)
      call add_cell(mx, my)
      ! The summary of every set (validate_sets): the wheel's Σ against the joined patch with the
      ! defaults and the main alternatives.
      call pool_wheel('coupled', 'exact-ellipse', 1, error)
      if (.not. allocated(error)) call pool_wheel('local-hertz', 'exact-ellipse', 2, error)
      if (.not. allocated(error)) call pool_wheel('coupled', 'none', 3, error)
   contains
      !> The wheel's Σ F/(μ Σ F_n) over our patches for one normal reduction and correction,
      !> against CONTACT's joined f, to the summary's two-lobe set and the set of all positions.
      subroutine pool_wheel(reduction, correction, config, error)
         character(len=*), intent(in) :: reduction, correction
         integer, intent(in) :: config
         type(error_type), allocatable, intent(out) :: error
         type(tangential_options_type) :: options
         real(wp) :: sx(size(jx)), sy(size(jx)), f_max, load, f_z
         integer :: k, it

         f_z = 64700.0_wp
         do it = 1, 4
            call wheel_patches(prepared, y_ws, f_z, reduction, geometry, patches, error)
            if (allocated(error)) return
            if (it < 4) f_z = f_z*64700.0_wp/sum(patches%load)
         end do
         options = tangential
         call parse_correction(correction, options%correction, error)
         if (allocated(error)) return
         load = sum(patches%load)
         sx = 0.0_wp
         sy = 0.0_wp
         f_max = 0.0_wp
         do k = 1, size(patches)
            if (.not. (patches(k)%load > 0.0_wp)) cycle
            y_k = (geometry(k)%y_track - y_ref)/cos(delta)
            set%name = name
            ! The joined DOE's creepages: those of the lobe file's rows of lobe 1, in its order.
            set%phi = 1.0e-3_wp*pack(phi, nint(lobe) == 1)
            set%nux = pack(nux, nint(lobe) == 1) - set%phi*(y_k - y_geo)
            set%nuy = pack(nuy, nint(lobe) == 1)
            set%fx = jx
            set%fy = jy
            call solve_set(patches(k), reference_material(), options, set, gx, gy, error)
            if (allocated(error)) return
            sx = sx + patches(k)%load*gx/load
            sy = sy + patches(k)%load*gy/load
            f_max = max(f_max, maxval(hypot(gx, gy)))
         end do
         call pool_errors(set_two_lobe, config, abs(sx - jx), abs(sy - jy), f_max)
         call pool_errors(set_all_positions, config, abs(sx - jx), abs(sy - jy), f_max)
      end subroutine pool_wheel

      !> One cell against the joined patch's forces.
      subroutine add_cell(ox, oy)
         real(wp), intent(in) :: ox(:), oy(:)
         ex = error_stats(abs(ox - jx))
         ey = error_stats(abs(oy - jy))
         write (cell, '(f5.3,a,f5.3,a,f5.3,a,f5.3)') ex%max, ' / ', ey%max, ' ; ', ex%p80, &
            ' / ', ey%p80
         row = trim(row)//' '//trim(cell)//' |'
      end subroutine add_cell
   end subroutine lobe_doe

   !> A real as short text.
   pure function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=16) :: text
      write (text, '(f6.2)') x
   end function real_text

   !> Our patches at y_ws under the vertical load f_z with the given reduction: for each lobe,
   !> the track y and normal force of the patch whose reference point is nearest the lobe's.
   subroutine nearest_patch_loads(prepared, y_ws, f_z, reduction, y_lobe, y_ours, n_ours, error)
      type(prepared_profiles_type), intent(in) :: prepared
      real(wp), intent(in) :: y_ws, f_z, y_lobe(:)
      character(len=*), intent(in) :: reduction
      real(wp), intent(out) :: y_ours(:), n_ours(:)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: patches(:)
      integer :: best, il

      call wheel_patches(prepared, y_ws, f_z, reduction, geometry, patches, error)
      if (allocated(error)) return
      do il = 1, size(y_lobe)
         best = nearest(geometry, y_lobe(il))
         y_ours(il) = geometry(best)%y_track
         n_ours(il) = patches(best)%load
      end do
   end subroutine nearest_patch_loads

   !> The patches of the right wheel at y_ws and their normal solutions under the vertical load
   !> f_z (N) with the given reduction.
   subroutine wheel_patches(prepared, y_ws, f_z, reduction, geometry, patches, error)
      type(prepared_profiles_type), intent(in) :: prepared
      real(wp), intent(in) :: y_ws, f_z
      character(len=*), intent(in) :: reduction
      type(patch_geometry_type), allocatable, intent(out) :: geometry(:)
      type(normal_patch_type), allocatable, intent(out) :: patches(:)
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_options_type) :: options
      real(wp) :: dz
      integer :: k

      call find_contact_patches(prepared, wheelset_position_type(y_ws=y_ws), geometry, error)
      if (allocated(error)) return
      call new_normal_options(options, error, reduction=trim(reduction))
      if (allocated(error)) return
      allocate (contacts(size(geometry)), patches(size(geometry)))
      do k = 1, size(geometry)
         call prepare_normal_contact(contacts(k), geometry(k), options, reference_material(), &
            error)
         if (allocated(error)) return
      end do
      call solve_vertical_load(contacts, f_z, patches, dz, error)
   end subroutine wheel_patches

   !> The patch whose reference point (track y) is nearest y (mm).
   pure integer function nearest(geometry, y) result(best)
      type(patch_geometry_type), intent(in) :: geometry(:)
      real(wp), intent(in) :: y
      integer :: k
      best = 1
      do k = 2, size(geometry)
         if (abs(geometry(k)%y_track - y) < abs(geometry(best)%y_track - y)) best = k
      end do
   end function nearest

end module validate_lobes
