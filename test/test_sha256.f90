!> SHA-256 against the test vectors published with FIPS 180-4 (NIST examples): the
!! empty string, "abc", the 448-bit message and a million "a".
module test_sha256
    use brachistochrone_sha256, only: sha256_hex
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
    end subroutine run_sha256_tests

end module test_sha256
