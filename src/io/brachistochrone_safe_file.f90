!> The one writer of every output file: complete and correct under its name, or absent.
!!
!! An output is written to a temporary file *created* by this run in the target's
!! directory, `.NAME.XXXXXX.tmp` (six random letters and digits from `mkostemps`, which
!! opens with O_CREAT|O_EXCL: a planted file or link at that name is never followed or
!! written through, a new name is drawn instead; POSIX makes O_EXCL refuse a symbolic
!! link, so O_NOFOLLOW, whose value differs between Linux architectures, is not needed;
!! O_CLOEXEC is added and the mode set to 0666 & ~umask). Bytes go out through `write(2)` in
!! 1 MiB chunks, every return value and `errno` checked (libgfortran 12 reports iostat = 0
!! on a full disk, so Fortran I/O is not used for outputs); the file is `fsync`ed before
!! it is committed, and only while its name still holds this run's file (device and inode
!! of the open descriptor). Commit without `force` is `renameat2(RENAME_NOREPLACE)` (or
!! `link` + `unlink` where the file system lacks it), so an existing target, also one that
!! appears during the run, is never replaced; with `force`, `rename(2)` replaces a regular
!! file or a symbolic link (the link itself, never its target); a directory, device, FIFO
!! or socket is refused. The outputs of one run are committed together (`commit_outputs`):
!! when one commit fails the earlier ones are undone (a new file removed, a replaced one
!! restored from a hard-link backup), so all or none are in place.
!!
!! SIGTERM, SIGINT, SIGHUP and SIGPIPE remove this run's temporary files and end the
!! process with exit code 128 + signal (during the commit of several files the signal
!! waits until the set is committed, then the set is undone). Names of the temporary files
!! are kept as C strings in static storage for the handler, which calls only `unlink`
!! and `_exit` (async-signal-safe). A SIGKILL can leave `.NAME.XXXXXX.tmp` files (and,
!! during a --force commit, `.NAME.XXXXXX.old` hard links to a replaced file) behind.
!!
!! The output `-` is standard output (file descriptor 1): written through the same checked
!! writer, never synced or committed. Linux (glibc or musl): statx, renameat2, mkostemps.
module brachistochrone_safe_file
    use, intrinsic :: iso_c_binding, only: c_int, c_int16_t, c_int32_t, c_int64_t, c_char, &
            c_size_t, c_intptr_t, c_ptr, c_funptr, c_funloc, c_f_pointer, c_null_char, &
            c_associated
    use brachistochrone_strings, only: escape_text
    implicit none
    private

    public :: safe_file, open_output, finish_output, finish_outputs, commit_outputs, &
              discard_outputs
    public :: file_identity, same_file, same_name, standard_output
    public :: open_scratch, append_range, close_scratch
    public :: safe_ok, safe_refused, safe_io_error

    !> Status of `open_output`, `finish_output`, `commit_outputs`: done.
    integer, parameter :: safe_ok = 0
    !> Status: refused (the target exists without force, or is a directory, device, FIFO
    !! or socket, or appeared during the run); nothing was written. Exit code 1.
    integer, parameter :: safe_refused = 1
    !> Status: an I/O error (cannot create, write, sync or commit); the message names the
    !! file and the cause (strerror). Exit code 3.
    integer, parameter :: safe_io_error = 3
    !> The name that means standard output.
    character(len=*), parameter :: standard_output = '-'

    integer, parameter :: chunk = 1048576      ! bytes buffered before a write(2)
    integer, parameter :: scratch_chunk = 64*chunk ! a scratch file's: written only beyond
    integer, parameter :: max_slots = 16       ! temporary files of one run at a time
    integer, parameter :: max_path = 4096      ! PATH_MAX
    integer, parameter :: max_base = 200       ! NAME_MAX 255 minus '.', '.XXXXXX.tmp'
    integer(c_int), parameter :: at_fdcwd = -100_c_int, at_symlink_nofollow = 256_c_int, &
                                 at_empty_path = 4096_c_int, rename_noreplace = 1_c_int
    integer(c_int), parameter :: o_cloexec = 524288_c_int   ! 02000000 on Linux
    integer(c_int), parameter :: e_intr = 4, e_noent = 2, e_exist = 17, e_inval = 22, &
                                 e_pipe = 32, e_nosys = 38, e_opnotsupp = 95
    integer(c_intptr_t), parameter :: sig_ign = 1       ! SIG_IGN
    integer(c_int), parameter :: sigpipe = 13
    integer, parameter :: s_ifmt = int(o'170000'), s_ifreg = int(o'100000'), &
        s_iflnk = int(o'120000'), s_ifdir = int(o'040000'), s_ifchr = int(o'020000'), &
        s_ifblk = int(o'060000'), s_ififo = int(o'010000'), s_ifsock = int(o'140000')

    !> One output being written.
    type :: safe_file
        character(len=:), allocatable :: path      !! the target ('-': standard output)
        character(len=:), allocatable :: temporary !! where it is until committed
        character(len=:), allocatable :: backup    !! hard link to the file it replaced
        logical :: force = .false.                 !! may replace a regular file or link
        integer(c_int) :: fd = -1                  !! open descriptor (-1: not open)
        integer :: slot = 0                        !! its entry in the signal handler's list
        integer :: error = 0                       !! errno of the first failure (0: none)
        character(len=:), allocatable :: failed    !! the call that failed
        character(len=:), allocatable :: buffer    !! bytes not yet written
        integer :: used = 0                        !! bytes of `buffer` in use
        integer(c_int64_t) :: flushed = 0          !! bytes written out before `buffer`
        integer(c_int64_t) :: unsynced = 0         !! of them, not yet sent to the disk
        logical :: committed = .false.             !! in place under `path`
    contains
        !> Append one line (a newline is added); errors are kept for `finish_output`.
        procedure :: put => put_line
        !> The output is open (requested and created).
        procedure :: is_open
        !> Append bytes of a scratch file (`open_scratch`).
        procedure :: append_range
    end type safe_file

    !> statx(2) result: the same layout on every Linux architecture.
    type, bind(c) :: statx_type
        integer(c_int32_t) :: mask, blksize
        integer(c_int64_t) :: attributes
        integer(c_int32_t) :: nlink, uid, gid
        integer(c_int16_t) :: mode, spare0
        integer(c_int64_t) :: ino, size, blocks, attributes_mask
        integer(c_int64_t) :: times(8)
        integer(c_int32_t) :: rdev_major, rdev_minor, dev_major, dev_minor
        integer(c_int64_t) :: spare(14)
    end type statx_type

    ! What the signal handler may touch: static, NUL-terminated names; volatile flags.
    character(kind=c_char), save :: slot_name(max_path + 1, max_slots)
    logical, volatile, save :: slot_used(max_slots) = .false.
    logical, volatile, save :: committing = .false.
    integer(c_int), volatile, save :: pending_signal = 0
    logical, save :: handlers_installed = .false.

    interface
        function c_mkostemps(template, suffix_length, flags) bind(c, name='mkostemps') &
                result(fd)
            import :: c_char, c_int
            character(kind=c_char), intent(inout) :: template(*)
            integer(c_int), value :: suffix_length, flags
            integer(c_int) :: fd
        end function c_mkostemps
        function c_write(fd, buffer, count) bind(c, name='write') result(written)
            import :: c_int, c_char, c_size_t, c_intptr_t
            integer(c_int), value :: fd
            character(kind=c_char), intent(in) :: buffer(*)
            integer(c_size_t), value :: count
            integer(c_intptr_t) :: written
        end function c_write
        function c_pread(fd, buffer, count, offset) bind(c, name='pread') result(done)
            import :: c_int, c_char, c_size_t, c_intptr_t, c_int64_t
            integer(c_int), value :: fd
            character(kind=c_char), intent(inout) :: buffer(*)
            integer(c_size_t), value :: count
            integer(c_int64_t), value :: offset
            integer(c_intptr_t) :: done
        end function c_pread
        function c_sync_file_range(fd, offset, bytes, flags) bind(c, name='sync_file_range') &
                result(code)
            import :: c_int, c_int64_t
            integer(c_int), value :: fd, flags
            integer(c_int64_t), value :: offset, bytes
            integer(c_int) :: code
        end function c_sync_file_range
        function c_fsync(fd) bind(c, name='fsync') result(code)
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: code
        end function c_fsync
        function c_close(fd) bind(c, name='close') result(code)
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: code
        end function c_close
        function c_fchmod(fd, mode) bind(c, name='fchmod') result(code)
            import :: c_int
            integer(c_int), value :: fd, mode
            integer(c_int) :: code
        end function c_fchmod
        function c_umask(mask) bind(c, name='umask') result(old)
            import :: c_int
            integer(c_int), value :: mask
            integer(c_int) :: old
        end function c_umask
        function c_unlink(path) bind(c, name='unlink') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: code
        end function c_unlink
        function c_link(old, new) bind(c, name='link') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: code
        end function c_link
        function c_rename(old, new) bind(c, name='rename') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: code
        end function c_rename
        function c_renameat2(old_dir, old, new_dir, new, flags) bind(c, name='renameat2') &
                result(code)
            import :: c_char, c_int
            integer(c_int), value :: old_dir, new_dir, flags
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: code
        end function c_renameat2
        function c_statx(dir, path, flags, mask, buffer) bind(c, name='statx') result(code)
            import :: c_char, c_int, statx_type
            integer(c_int), value :: dir, flags, mask
            character(kind=c_char), intent(in) :: path(*)
            type(statx_type), intent(out) :: buffer
            integer(c_int) :: code
        end function c_statx
        function c_errno_location() bind(c, name='__errno_location') result(location)
            import :: c_ptr
            type(c_ptr) :: location
        end function c_errno_location
        function c_strerror(code) bind(c, name='strerror') result(text)
            import :: c_int, c_ptr
            integer(c_int), value :: code
            type(c_ptr) :: text
        end function c_strerror
        function c_strlen(text) bind(c, name='strlen') result(length)
            import :: c_ptr, c_size_t
            type(c_ptr), value :: text
            integer(c_size_t) :: length
        end function c_strlen
        function c_signal(signal_number, handler) bind(c, name='signal') result(old)
            import :: c_int, c_funptr
            integer(c_int), value :: signal_number
            type(c_funptr), value :: handler
            type(c_funptr) :: old
        end function c_signal
        function c_atexit(handler) bind(c, name='atexit') result(code)
            import :: c_int, c_funptr
            type(c_funptr), value :: handler
            integer(c_int) :: code
        end function c_atexit
        subroutine c_exit_now(code) bind(c, name='_exit')
            import :: c_int
            integer(c_int), value :: code
        end subroutine c_exit_now
    end interface

contains

    !> Start writing `path`: standard output for '-'; otherwise check the target (without
    !! `force` it must not exist; with `force` it may be a regular file or a symbolic link)
    !! and create the temporary file. status: `safe_ok`, `safe_refused` or `safe_io_error`,
    !! with `message`. On failure `file` is not open and nothing was created.
    subroutine open_output(file, path, force, status, message)
        type(safe_file), intent(out) :: file                   !! the output
        character(len=*), intent(in) :: path                   !! the target
        logical, intent(in) :: force                           !! may replace
        integer, intent(out) :: status                         !! safe_ok, _refused, _io_error
        character(len=:), allocatable, intent(out) :: message  !! why not
        character(len=:), allocatable :: template
        integer(c_int) :: mask
        integer :: slot

        file%path = path
        file%force = force
        file%failed = ''
        message = ''
        if (path == standard_output) then
            status = safe_ok
            file%fd = 1
            call install_handlers()
            allocate (character(len=chunk) :: file%buffer)
            return
        end if
        call check_target(path, force, status, message)
        if (status /= safe_ok) return
        template = temporary_template(path)
        slot = findloc(slot_used, .false., dim=1)
        if (len(template) > max_path .or. slot == 0) then
            status = safe_io_error
            message = 'cannot write '//escape_text(path)//': '// &
                      trim(merge('the name is too long      ', 'too many outputs at a time', &
                                 slot /= 0))
            return
        end if
        call install_handlers()
        slot_name(:, slot) = c_null_char
        slot_name(1:len(template), slot) = transfer(template, slot_name(:len(template), slot))
        ! listed before it exists, so that a signal between the create and the return
        ! still removes it (before the create the name does not exist: unlink fails)
        slot_used(slot) = .true.
        file%fd = c_mkostemps(slot_name(1, slot), 4_c_int, o_cloexec)
        if (file%fd < 0) then
            slot_used(slot) = .false.
            status = safe_io_error
            message = 'cannot write '//escape_text(path)//': cannot create a file in its '// &
                      'directory ('// &
                      error_text(errno())//')'
            return
        end if
        file%slot = slot
        file%temporary = c_text(slot_name(:, slot))
        mask = c_umask(int(o'022', c_int))
        mask = c_umask(mask)
        if (c_fchmod(file%fd, iand(int(o'666', c_int), not(mask))) /= 0) &
            call remember(file, 'fchmod')
        allocate (character(len=chunk) :: file%buffer)
    end subroutine open_output

    !> A scratch file for the run's output `near`: written with `put`, read back with
    !! `append_range`, never committed; its first 64 MiB stay in memory (only what is
    !! written beyond goes to the file). It is created like a temporary file (in the
    !! directory of `near`, so a full disk there is found, listed for the signal handler
    !! meanwhile) and removed at once, so it has no name and leaves nothing behind. Write
    !! errors are kept as for an output and passed on by `append_range` (messages name
    !! `near`). status: `safe_ok` or `safe_io_error` (cannot create, with `message`).
    subroutine open_scratch(file, near, status, message, memory)
        type(safe_file), intent(out) :: file                   !! the scratch file
        character(len=*), intent(in) :: near                   !! the output it serves
        integer, intent(out) :: status                         !! safe_ok or safe_io_error
        character(len=:), allocatable, intent(out) :: message  !! why not
        integer, intent(in), optional :: memory  !! bytes kept in memory (default 64 MiB)
        character(len=:), allocatable :: template
        integer :: slot
        file%path = near
        file%failed = ''
        message = ''
        status = safe_io_error
        template = temporary_template(near)
        slot = findloc(slot_used, .false., dim=1)
        if (len(template) > max_path .or. slot == 0) then
            message = 'cannot write '//escape_text(near)//': no room for a scratch file'
            return
        end if
        call install_handlers()
        slot_name(:, slot) = c_null_char
        slot_name(1:len(template), slot) = transfer(template, slot_name(:len(template), slot))
        slot_used(slot) = .true.
        file%fd = c_mkostemps(slot_name(1, slot), 4_c_int, o_cloexec)
        if (file%fd < 0) then
            slot_used(slot) = .false.
            message = 'cannot write '//escape_text(near)//': cannot create a scratch file '// &
                      'in its directory ('//error_text(errno())//')'
            return
        end if
        if (c_unlink(slot_name(1, slot)) /= 0) call remember(file, 'unlink')
        slot_used(slot) = .false.
        if (present(memory)) then
            allocate (character(len=max(memory, 256)) :: file%buffer)
        else
            allocate (character(len=scratch_chunk) :: file%buffer)
        end if
        status = safe_ok
    end subroutine open_scratch

    !> Close a scratch file (`open_scratch`); nothing is left of it.
    subroutine close_scratch(file)
        type(safe_file), intent(inout) :: file !! the scratch file
        integer(c_int) :: code
        if (file%fd >= 0) code = c_close(file%fd)
        file%fd = -1
    end subroutine close_scratch

    !> Append `length` bytes of the scratch file `source` from byte `offset` (0 first) to
    !! this output, through its buffer: from `source`'s buffer where they still are, else
    !! with pread(2) (EINTR retried). A write error of `source` becomes this output's
    !! error (reported by `finish_output`), as does a failed read.
    subroutine append_range(self, source, offset, length)
        class(safe_file), intent(inout) :: self     !! the output
        type(safe_file), intent(inout) :: source    !! the scratch file
        integer(c_int64_t), intent(in) :: offset    !! where the bytes start in `source`
        integer(c_int64_t), intent(in) :: length    !! how many
        integer(c_int64_t) :: done, at
        integer(c_intptr_t) :: got
        integer :: room, start
        if (source%error /= 0 .and. self%error == 0) then
            self%error = source%error
            self%failed = source%failed
        end if
        if (self%fd < 0 .or. source%fd < 0) return
        done = 0
        do while (done < length .and. self%error == 0)
            if (self%used == len(self%buffer)) call flush_buffer(self)
            room = int(min(length - done, int(len(self%buffer) - self%used, c_int64_t)))
            at = offset + done
            if (at >= source%flushed) then           ! still in memory: written from there
                start = int(at - source%flushed)
                room = int(min(length - done, int(source%used - start, c_int64_t)))
                if (room <= 0) then
                    call remember(self, 'read', 5)     ! EIO: beyond the scratch file
                    exit
                end if
                call flush_buffer(self)
                call write_bytes(self, source%buffer(start + 1:start + room))
                call written_out(self, int(room, c_int64_t))
                done = done + room
                cycle
            end if
            got = c_pread(source%fd, self%buffer(self%used + 1:), &
                          int(min(int(room, c_int64_t), source%flushed - at), c_size_t), at)
            if (got > 0) then
                done = done + got
                self%used = self%used + int(got)
            else if (got == 0) then
                call remember(self, 'read', 5)     ! EIO: the scratch file is short
            else if (errno() /= e_intr) then
                call remember(self, 'read')
            end if
        end do
    end subroutine append_range

    !> Without force the target must not exist; with force it may be a regular file or a
    !! symbolic link (never followed). Other errors than "no such file" are I/O errors.
    subroutine check_target(path, force, status, message)
        character(len=*), intent(in) :: path
        logical, intent(in) :: force
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: message
        type(statx_type) :: info
        integer :: kind, code
        status = safe_ok
        message = ''
        if (c_statx(at_fdcwd, path//c_null_char, at_symlink_nofollow, 3_c_int, info) /= 0) then
            code = errno()
            if (code == e_noent) return     ! a missing directory is found by the create
            status = safe_io_error
            message = 'cannot write '//escape_text(path)//': '//error_text(code)
            return
        end if
        kind = iand(int(info%mode), s_ifmt)
        if (.not. force) then
            status = safe_refused
            message = escape_text(path)//' exists; use --force to replace it, or choose '// &
                      'another name'
        else if (kind /= s_ifreg .and. kind /= s_iflnk) then
            status = safe_refused
            message = escape_text(path)//' is '//kind_word(kind)//'; --force replaces only '// &
                      'regular '// &
                      'files and symbolic links'
        end if
    end subroutine check_target

    pure function kind_word(kind) result(word)
        integer, intent(in) :: kind
        character(len=:), allocatable :: word
        select case (kind)
        case (s_ifdir);  word = 'a directory'
        case (s_ifchr);  word = 'a character device'
        case (s_ifblk);  word = 'a block device'
        case (s_ififo);  word = 'a FIFO'
        case (s_ifsock); word = 'a socket'
        case default;    word = 'not a regular file'
        end select
    end function kind_word

    !> `DIR/.NAME.XXXXXX.tmp` for `DIR/NAME` (NAME cut to `max_base` characters).
    pure function temporary_template(path) result(template)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: template
        integer :: slash
        slash = index(path, '/', back=.true.)
        template = path(:slash)//'.'//path(slash + 1:min(len(path), slash + max_base))// &
                   '.XXXXXX.tmp'
    end function temporary_template

    !> The output is open.
    pure logical function is_open(self)
        class(safe_file), intent(in) :: self !! the output
        is_open = self%fd >= 0
    end function is_open

    !> Append `line` and a newline; write out the buffer when it is full.
    subroutine put_line(self, line)
        class(safe_file), intent(inout) :: self !! the output
        character(len=*), intent(in) :: line    !! the text, without newline
        integer :: length
        if (self%fd < 0 .or. self%error /= 0) return
        length = len(line) + 1
        if (self%used + length > len(self%buffer)) call flush_buffer(self)
        if (length > len(self%buffer)) then
            call write_bytes(self, line//new_line('a'))
            call written_out(self, int(length, c_int64_t))
        else
            self%buffer(self%used + 1:self%used + length - 1) = line
            self%buffer(self%used + length:self%used + length) = new_line('a')
            self%used = self%used + length
        end if
    end subroutine put_line

    subroutine flush_buffer(self)
        class(safe_file), intent(inout) :: self
        if (self%used > 0) call write_bytes(self, self%buffer(:self%used))
        call written_out(self, int(self%used, c_int64_t))
        self%used = 0
    end subroutine flush_buffer

    !> `bytes` more were written out. Every half MiB of an output file, start writing it
    !! to disk (SYNC_FILE_RANGE_WRITE, asynchronous), so that the fsync at the end has
    !! little left to wait for.
    subroutine written_out(self, bytes)
        class(safe_file), intent(inout) :: self
        integer(c_int64_t), intent(in) :: bytes
        integer(c_int) :: code
        self%flushed = self%flushed + bytes
        self%unsynced = self%unsynced + bytes
        if (self%unsynced < chunk/2 .or. .not. allocated(self%temporary)) return
        if (self%error == 0) code = c_sync_file_range(self%fd, 0_c_int64_t, 0_c_int64_t, &
                                                      2_c_int)
        self%unsynced = 0
    end subroutine written_out

    !> write(2) until every byte is out; EINTR is retried, any other error is kept.
    subroutine write_bytes(self, text)
        class(safe_file), intent(inout) :: self
        character(len=*), intent(in) :: text
        integer(c_size_t) :: done, total
        integer(c_intptr_t) :: written
        done = 0
        total = len(text, c_size_t)
        do while (done < total .and. self%error == 0)
            written = c_write(self%fd, text(done + 1:), total - done)
            if (written > 0) then
                done = done + written
            else if (written == 0) then
                call remember(self, 'write', 5)    ! EIO: no progress
            else if (errno() /= e_intr) then
                call remember(self, 'write')
            end if
        end do
    end subroutine write_bytes

    !> Keep the first failure: the call and errno (or `code`).
    subroutine remember(self, call_name, code)
        class(safe_file), intent(inout) :: self
        character(len=*), intent(in) :: call_name
        integer, intent(in), optional :: code
        if (self%error /= 0) return
        self%error = errno()
        if (present(code)) self%error = code
        if (self%error == 0) self%error = 5
        self%failed = call_name
    end subroutine remember

    !> Write out what is buffered and sync the file to disk (standard output: only write
    !! out). status: `safe_ok`, or `safe_io_error` with a message naming the file and the
    !! cause of the first failure of any write so far.
    subroutine finish_output(file, status, message)
        type(safe_file), intent(inout) :: file                 !! the output
        integer, intent(out) :: status                         !! safe_ok or safe_io_error
        character(len=:), allocatable, intent(out) :: message  !! what failed
        call finish_one(file, .true., status, message)
    end subroutine finish_output

    !> `finish_output` for each of `files` in turn, their `fsync`s done at once by the
    !! OpenMP threads (the disk's waits overlap). status and message: those of the first
    !! output that failed, in order (`safe_ok` when none did).
    subroutine finish_outputs(files, status, message)
        type(safe_file), intent(inout) :: files(:)             !! the outputs
        integer, intent(out) :: status                         !! safe_ok or safe_io_error
        character(len=:), allocatable, intent(out) :: message  !! what failed
        integer :: errors(size(files)), k
        do k = 1, size(files)
            if (files(k)%fd >= 0) call flush_buffer(files(k))
        end do
        errors = 0
        !$omp parallel do schedule(static, 1) default(shared) private(k)
        do k = 1, size(files)
            if (files(k)%fd < 0 .or. files(k)%error /= 0) cycle
            if (files(k)%path == standard_output) cycle
            if (c_fsync(files(k)%fd) /= 0) errors(k) = max(errno(), 1)
        end do
        !$omp end parallel do
        do k = 1, size(files)
            if (errors(k) /= 0) call remember(files(k), 'fsync', errors(k))
            call finish_one(files(k), .false., status, message)
            if (status /= safe_ok) return
        end do
    end subroutine finish_outputs

    !> `finish_output`, with the fsync (`sync`) or without (done already).
    subroutine finish_one(file, sync, status, message)
        type(safe_file), intent(inout) :: file
        logical, intent(in) :: sync
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: message
        status = safe_ok
        message = ''
        if (file%fd < 0) return
        call flush_buffer(file)
        if (sync .and. file%path /= standard_output .and. file%error == 0) then
            if (c_fsync(file%fd) /= 0) call remember(file, 'fsync')
        end if
        if (file%error == e_pipe .and. file%path == standard_output) then
            ! the reader has gone (SIGPIPE ignored by the parent): end quietly, as SIGPIPE
            call on_exit()
            call c_exit_now(128_c_int + sigpipe)
        else if (file%error /= 0) then
            status = safe_io_error
            if (file%path == standard_output) then
                message = 'cannot write to standard output: '//error_text(file%error)
            else
                message = 'cannot write '//escape_text(file%path)//': '//error_text(file%error)// &
                          ' (in '//file%failed//')'
            end if
        end if
    end subroutine finish_one

    !> Put every finished output in place, or none: when one commit fails, the earlier
    !! ones are undone and every temporary file is removed. Standard output is skipped.
    !! status: `safe_ok`; `safe_refused` (a target appeared without force, or became
    !! a directory, device, FIFO or socket); `safe_io_error` (the commit failed).
    !! A termination signal meanwhile waits; the set is then undone and the process ends
    !! with 128 + signal.
    subroutine commit_outputs(files, status, message)
        type(safe_file), intent(inout) :: files(:)             !! finished outputs
        integer, intent(out) :: status                         !! safe_ok, _refused, _io_error
        character(len=:), allocatable, intent(out) :: message  !! what failed
        integer :: k, j
        status = safe_ok
        message = ''
        committing = .true.
        do k = 1, size(files)
            if (files(k)%fd < 0) cycle
            if (files(k)%path == standard_output) cycle
            call commit_one(files(k), status, message)
            if (status /= safe_ok) exit
        end do
        if (status /= safe_ok .or. pending_signal /= 0) then
            do j = size(files), 1, -1
                call undo_one(files(j))
            end do
        end if
        ! the replaced files' data is freed here: by the threads at once
        !$omp parallel do schedule(static, 1) default(shared) private(k)
        do k = 1, size(files)
            if (.not. (files(k)%committed .and. allocated(files(k)%backup))) cycle
            if (c_unlink(files(k)%backup//c_null_char) /= 0) continue
        end do
        !$omp end parallel do
        call discard_outputs(files)
        committing = .false.
        if (pending_signal /= 0) call c_exit_now(128_c_int + pending_signal)
    end subroutine commit_outputs

    !> Commit one output: without force never over an existing name; with force over a
    !! regular file or a symbolic link, keeping a hard link to it until the set is in.
    subroutine commit_one(file, status, message)
        type(safe_file), intent(inout) :: file
        integer, intent(inout) :: status
        character(len=:), allocatable, intent(inout) :: message
        character(len=:), allocatable :: temporary, target
        integer(c_int) :: code
        temporary = file%temporary//c_null_char
        target = file%path//c_null_char
        if (.not. holds_descriptor(file%temporary, file%fd)) then
            status = safe_io_error
            message = 'cannot put the finished '//escape_text(file%path)//' in place: its '// &
                      'temporary file '//escape_text(file%temporary)//' was removed or '// &
                      'replaced by another process'
            return
        end if
        if (file%force) then
            call check_target(file%path, .true., status, message)
            if (status /= safe_ok) return
            file%backup = file%temporary(:len(file%temporary) - 4)//'.old'
            if (c_link(target, file%backup//c_null_char) /= 0) deallocate (file%backup)
            code = c_rename(temporary, target)
        else
            code = c_renameat2(at_fdcwd, temporary, at_fdcwd, target, rename_noreplace)
            if (code /= 0 .and. any(errno() == [e_inval, e_nosys, e_opnotsupp])) then
                code = c_link(temporary, target)
                if (code == 0) then
                    if (c_unlink(temporary) /= 0) continue   ! a stray name; the data is in
                end if
            end if
        end if
        if (code == 0) then
            file%committed = .true.
            slot_used(file%slot) = .false.    ! the temporary name is gone
        else if (errno() == e_exist) then
            status = safe_refused
            message = escape_text(file%path)//' appeared during the run and was kept; use '// &
                      '--force to '// &
                      'replace it, or choose another name'
        else
            status = safe_io_error
            message = 'cannot put the finished '//escape_text(file%path)//' in place: '// &
                      error_text(errno())
        end if
        if (code /= 0 .and. allocated(file%backup)) then
            code = c_unlink(file%backup//c_null_char)
            deallocate (file%backup)
        end if
    end subroutine commit_one

    !> Undo a commit of this run: restore the replaced file, or remove the new one (only
    !! when the name still holds this run's file).
    subroutine undo_one(file)
        type(safe_file), intent(inout) :: file
        integer(c_int) :: code
        if (.not. file%committed) return
        if (allocated(file%backup)) then
            code = c_rename(file%backup//c_null_char, file%path//c_null_char)
            deallocate (file%backup)
        else if (holds_descriptor(file%path, file%fd)) then
            code = c_unlink(file%path//c_null_char)
        end if
        file%committed = .false.
    end subroutine undo_one

    !> `path` (not followed) is the file open as `fd`.
    logical function holds_descriptor(path, fd)
        character(len=*), intent(in) :: path
        integer(c_int), intent(in) :: fd
        type(statx_type) :: at_path, at_fd
        holds_descriptor = .false.
        if (c_statx(at_fdcwd, path//c_null_char, at_symlink_nofollow, 256_c_int, at_path) &
            /= 0) return
        if (c_statx(fd, c_null_char, at_empty_path, 256_c_int, at_fd) /= 0) return
        holds_descriptor = at_path%ino == at_fd%ino .and. at_path%dev_major == &
            at_fd%dev_major .and. at_path%dev_minor == at_fd%dev_minor
    end function holds_descriptor

    !> Close every output and remove the temporary files not committed (the error path,
    !! and the end of `commit_outputs`). Standard output is not closed.
    subroutine discard_outputs(files)
        type(safe_file), intent(inout) :: files(:) !! the outputs
        integer :: k
        integer(c_int) :: code
        do k = 1, size(files)
            if (files(k)%fd < 0) cycle
            if (files(k)%path /= standard_output) then
                if (.not. files(k)%committed) code = c_unlink(files(k)%temporary//c_null_char)
                code = c_close(files(k)%fd)
                if (files(k)%slot > 0) slot_used(files(k)%slot) = .false.
            end if
            files(k)%fd = -1
            files(k)%slot = 0
        end do
    end subroutine discard_outputs

    !> Identity of an existing file: device and inode (`follow`: of what a link points to).
    subroutine file_identity(path, follow, exists, device, inode)
        character(len=*), intent(in) :: path   !! the name
        logical, intent(in) :: follow          !! follow a symbolic link
        logical, intent(out) :: exists         !! the name exists
        integer(c_int64_t), intent(out) :: device, inode !! its identity (0 if absent)
        type(statx_type) :: info
        exists = c_statx(at_fdcwd, path//c_null_char, merge(0_c_int, at_symlink_nofollow, &
                         follow), 256_c_int, info) == 0
        device = 0
        inode = 0
        if (.not. exists) return
        device = ior(shiftl(int(info%dev_major, c_int64_t), 32), &
                     iand(int(info%dev_minor, c_int64_t), 4294967295_c_int64_t))
        inode = info%ino
    end subroutine file_identity

    !> Both names exist and are the same file (links followed).
    logical function same_file(a, b)
        character(len=*), intent(in) :: a, b !! two names
        logical :: exists_a, exists_b
        integer(c_int64_t) :: device_a, inode_a, device_b, inode_b
        call file_identity(a, .true., exists_a, device_a, inode_a)
        call file_identity(b, .true., exists_b, device_b, inode_b)
        same_file = exists_a .and. exists_b .and. device_a == device_b .and. inode_a == inode_b
    end function same_file

    !> The two names are the same entry: the same directory (however spelt) and the
    !! same last component, whether or not the file exists yet.
    logical function same_name(a, b)
        character(len=*), intent(in) :: a, b !! two names
        logical :: exists_a, exists_b
        integer(c_int64_t) :: device_a, inode_a, device_b, inode_b
        same_name = .false.
        if (base_name(a) /= base_name(b)) return
        call file_identity(directory_name(a), .true., exists_a, device_a, inode_a)
        call file_identity(directory_name(b), .true., exists_b, device_b, inode_b)
        if (exists_a .and. exists_b) then
            same_name = device_a == device_b .and. inode_a == inode_b
        else
            same_name = directory_name(a) == directory_name(b)
        end if
    end function same_name

    pure function base_name(path) result(name)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: name
        name = path(index(path, '/', back=.true.) + 1:)
    end function base_name

    pure function directory_name(path) result(name)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: name
        integer :: slash
        slash = index(path, '/', back=.true.)
        if (slash == 0) then
            name = '.'
        else if (slash == 1) then
            name = '/'
        else
            name = path(:slash - 1)
        end if
    end function directory_name

    !> The current errno.
    integer function errno()
        integer(c_int), pointer :: location
        call c_f_pointer(c_errno_location(), location)
        errno = int(location)
    end function errno

    !> strerror(code).
    function error_text(code) result(text)
        integer, intent(in) :: code
        character(len=:), allocatable :: text
        type(c_ptr) :: pointer
        character(kind=c_char), pointer :: letters(:)
        integer :: length, i
        pointer = c_strerror(int(code, c_int))
        if (.not. c_associated(pointer)) then
            text = 'error '
            return
        end if
        length = int(c_strlen(pointer))
        call c_f_pointer(pointer, letters, [length])
        allocate (character(len=length) :: text)
        do i = 1, length
            text(i:i) = letters(i)
        end do
    end function error_text

    !> Fortran text of a NUL-terminated C string.
    pure function c_text(letters) result(text)
        character(kind=c_char), intent(in) :: letters(:)
        character(len=:), allocatable :: text
        integer :: length, i
        length = findloc(letters, c_null_char, dim=1) - 1
        if (length < 0) length = size(letters)
        allocate (character(len=length) :: text)
        do i = 1, length
            text(i:i) = letters(i)
        end do
    end function c_text

    !> SIGHUP, SIGINT, SIGPIPE, SIGTERM run `on_signal`; the exit of the program (also a
    !! runtime error's) runs `on_exit`. Once.
    subroutine install_handlers()
        type(c_funptr) :: old
        integer(c_int) :: code
        integer :: k
        integer(c_int), parameter :: signals(4) = [1_c_int, 2_c_int, sigpipe, 15_c_int]
        if (handlers_installed) return
        handlers_installed = .true.
        do k = 1, size(signals)
            old = c_signal(signals(k), c_funloc(on_signal))
            ! a signal ignored by the parent (nohup: SIGHUP) stays ignored
            if (transfer(old, 0_c_intptr_t) == sig_ign) old = c_signal(signals(k), old)
        end do
        code = c_atexit(c_funloc(on_exit))
    end subroutine install_handlers

    !> Remove this run's temporary files and end with 128 + signal. Only unlink and _exit.
    subroutine on_signal(signal_number) bind(c)
        integer(c_int), value :: signal_number
        if (committing) then
            pending_signal = signal_number
            return
        end if
        call on_exit()
        call c_exit_now(128_c_int + signal_number)
    end subroutine on_signal

    !> Remove the temporary files still listed (normal paths have removed them already).
    subroutine on_exit() bind(c)
        integer :: k
        integer(c_int) :: code
        do k = 1, max_slots
            if (slot_used(k)) then
                code = c_unlink(slot_name(1, k))
                slot_used(k) = .false.
            end if
        end do
    end subroutine on_exit

end module brachistochrone_safe_file
