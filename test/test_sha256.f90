!> SHA-256 against the test vectors published with FIPS 180-4 (NIST examples): the
!! empty string, "abc", the 448-bit message and a million "a"; and `integer_text`
!! against gfortran's own `write(i0)` at the extremes.
module test_sha256
    use, intrinsic :: iso_fortran_env, only: int64
    use brachistochrone_sha256, only: sha256_hex
    use brachistochrone_strings, only: integer_text
    use testing, only: check, section
    implicit none
    private

    public :: run_sha256_tests

contains

    subroutine run_sha256_tests()
        call section('io: SHA-256 (FIPS 180-4 examples)')
        call check(sha256_hex('') == &
                   'e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855', &
                   'empty string')
        call check(sha256_hex('abc') == &
                   'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad', &
                   '"abc" (one block)')
        call check(sha256_hex('abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq') == &
                   '248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1', &
                   '448-bit message (padding in a second block)')
        call check(sha256_hex(repeat('a', 1000000)) == &
                   'cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0', &
                   'one million "a"')
        call integer_texts()
    end subroutine run_sha256_tests

    subroutine integer_texts()
        integer, parameter :: small(8) = [0, 1, -1, 9, 10, -10, huge(1), -huge(1) - 1]
        integer(int64), parameter :: large(4) = [huge(1_int64), -huge(1_int64) - 1_int64, &
                                                 1234567890123_int64, -100000_int64]
        character(len=24) :: expected
        integer :: k
        logical :: same
        call section('io: integer text (without internal I/O) against write(i0)')
        same = .true.
        do k = 1, size(small)
            write (expected, '(i0)') small(k)
            same = same .and. integer_text(small(k)) == trim(expected)
        end do
        do k = 1, size(large)
            write (expected, '(i0)') large(k)
            same = same .and. integer_text(large(k)) == trim(expected)
        end do
        call check(same, 'integer_text = write(i0) for 0, +-1, +-9, +-10, the extremes')
    end subroutine integer_texts

end module test_sha256
