!> What a batch driver needs besides input and output: dates and progress reports.
module brachistochrone_run_support
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use brachistochrone_version, only: program_name
    use brachistochrone_kinds, only: qp
    use brachistochrone_strings, only: integer_text
    implicit none
    private

    public :: timestamp, progress_type, median, sort_times

    !> Progress of a long loop, reported on stderr (never stdout): percent, rate, time
    !! left; the first report after 2 s, then every 5 s. Safe to step from OpenMP threads.
    type :: progress_type
        logical :: enabled = .false.
        integer :: total = 0
        integer :: done = 0
        integer(int64) :: started = 0, last_report = 0, rate = 1
        character(len=:), allocatable :: noun   !! what is counted ('endpoints')
        character(len=:), allocatable :: verb   !! what was done to them ('solved')
    contains
        procedure :: start => progress_start
        procedure :: step => progress_step
        procedure :: finish => progress_finish
    end type progress_type

contains

    !> ISO 8601 date and time: now, or SOURCE_DATE_EPOCH (seconds since 1970, UTC) when
    !! that variable is set, for reproducible output files.
    function timestamp() result(text)
        character(len=:), allocatable :: text
        character(len=8) :: date
        character(len=10) :: time
        character(len=5) :: zone
        character(len=32) :: epoch_text
        integer :: length, status, ios
        integer(int64) :: epoch
        call get_environment_variable('SOURCE_DATE_EPOCH', epoch_text, length, status)
        if (status == 0 .and. length > 0) then
            read (epoch_text, *, iostat=ios) epoch
            if (ios == 0) then
                text = utc_from_epoch(epoch)
                return
            end if
        end if
        call date_and_time(date, time, zone)
        text = date(1:4)//'-'//date(5:6)//'-'//date(7:8)//'T'//time(1:2)//':'// &
               time(3:4)//':'//time(5:6)//zone
    end function timestamp

    !> Civil UTC date of a Unix time (days-from-civil inverse, proleptic Gregorian).
    pure function utc_from_epoch(epoch) result(text)
        integer(int64), intent(in) :: epoch
        character(len=:), allocatable :: text
        integer(int64) :: days, seconds, era, day_of_era, year_of_era, day_of_year, mp, &
                          day, month, year
        character(len=32) :: buffer
        days = epoch/86400_int64
        seconds = epoch - 86400_int64*days
        if (seconds < 0) then
            seconds = seconds + 86400_int64
            days = days - 1
        end if
        days = days + 719468_int64
        era = merge(days, days - 146096_int64, days >= 0)/146097_int64
        day_of_era = days - era*146097_int64
        year_of_era = (day_of_era - day_of_era/1460_int64 + day_of_era/36524_int64 &
                       - day_of_era/146096_int64)/365_int64
        year = year_of_era + era*400_int64
        day_of_year = day_of_era - (365_int64*year_of_era + year_of_era/4_int64 &
                                    - year_of_era/100_int64)
        mp = (5_int64*day_of_year + 2_int64)/153_int64
        day = day_of_year - (153_int64*mp + 2_int64)/5_int64 + 1_int64
        month = merge(mp + 3_int64, mp - 9_int64, mp < 10_int64)
        if (month <= 2) year = year + 1
        write (buffer, '(i4.4,a,i2.2,a,i2.2,a,i2.2,a,i2.2,a,i2.2,a)') year, '-', month, '-', &
            day, 'T', seconds/3600, ':', mod(seconds, 3600_int64)/60, ':', &
            mod(seconds, 60_int64), '+0000'
        text = trim(buffer)
    end function utc_from_epoch

    subroutine progress_start(self, total, enabled, noun, verb)
        class(progress_type), intent(inout) :: self
        integer, intent(in) :: total     !! steps to come
        logical, intent(in) :: enabled   !! report at all
        character(len=*), intent(in), optional :: noun !! what a step is (default endpoints)
        character(len=*), intent(in), optional :: verb !! what was done (default solved)
        self%noun = 'endpoints'
        if (present(noun)) self%noun = noun
        self%verb = 'solved'
        if (present(verb)) self%verb = verb
        self%enabled = enabled
        self%total = total
        self%done = 0
        call system_clock(self%started, self%rate)
        self%last_report = self%started
    end subroutine progress_start

    !> One step done; reports at most every 5 s (checked every 64 steps).
    subroutine progress_step(self)
        class(progress_type), intent(inout) :: self
        integer :: done
        integer(int64) :: now
        real :: elapsed, speed
        if (.not. self%enabled) return
        !$omp atomic capture
        self%done = self%done + 1
        done = self%done
        !$omp end atomic
        if (mod(done, 64) /= 0) return
        call system_clock(now)
        !$omp critical (progress_report)
        elapsed = real(now - self%started)/real(self%rate)
        if (elapsed >= 2.0 .and. real(now - self%last_report)/real(self%rate) >= 5.0 &
            .or. (elapsed >= 2.0 .and. self%last_report == self%started)) then
            self%last_report = now
            speed = real(done)/max(elapsed, 1.0e-3)
            write (error_unit, '(a,f5.1,a,i0,a,i0,a,f0.1,a,a)') program_name//': ', &
                100.0*real(done)/real(self%total), '% (', done, '/', self%total, '), ', &
                speed, ' '//self%noun//'/s, ', duration(real(self%total - done)/speed)//' left'
        end if
        !$omp end critical (progress_report)
    end subroutine progress_step

    subroutine progress_finish(self)
        class(progress_type), intent(inout) :: self
        integer(int64) :: now
        real :: elapsed
        if (.not. self%enabled) return
        call system_clock(now)
        elapsed = real(now - self%started)/real(self%rate)
        if (elapsed >= 2.0) write (error_unit, '(a,i0,a,a,a,f0.1,a)') program_name// &
            ': '//self%verb//' ', self%total, ' '//self%noun//' in ', duration(elapsed), &
            ' (', real(self%total)/max(elapsed, 1.0e-3), ' '//self%noun//'/s)'
    end subroutine progress_finish

    pure function duration(seconds) result(text)
        real, intent(in) :: seconds
        character(len=:), allocatable :: text
        integer :: whole
        whole = nint(seconds)
        if (whole >= 3600) then
            text = integer_text(whole/3600)//'h'//integer_text(mod(whole, 3600)/60)//'m'
        else if (whole >= 60) then
            text = integer_text(whole/60)//'m'//integer_text(mod(whole, 60))//'s'
        else
            text = integer_text(whole)//'s'
        end if
    end function duration

    !> The median of `values` (the upper middle one for an even count), for timings.
    pure function median(values) result(middle)
        real(qp), intent(in) :: values(:) !! at least one value
        real(qp) :: middle
        real(qp) :: sorted(size(values)), swap
        integer :: a, b
        sorted = values
        do a = 2, size(sorted)
            do b = a, 2, -1
                if (sorted(b - 1) <= sorted(b)) exit
                swap = sorted(b)
                sorted(b) = sorted(b - 1)
                sorted(b - 1) = swap
            end do
        end do
        middle = sorted((size(sorted) + 1)/2)
    end function median

    !> Sort CPU times (default real, as `cpu_time` gives them) ascending in place
    !! (insertion sort: the timing examples' few thousand values).
    pure subroutine sort_times(times)
        real, intent(inout) :: times(:) !! the values, sorted on return
        real :: key
        integer :: i, j
        do i = 2, size(times)
            key = times(i)
            j = i - 1
            do while (j >= 1)
                if (times(j) <= key) exit
                times(j + 1) = times(j)
                j = j - 1
            end do
            times(j + 1) = key
        end do
    end subroutine sort_times

end module brachistochrone_run_support
