"""The tool's common behaviour: version, help, bad input gives one line on stderr and status 2."""


def test_version(cli):
    r = cli("version")
    assert r.returncode == 0
    assert r.stdout.startswith("poinsot ")


def test_no_command_is_an_error(cli):
    r = cli()
    assert r.returncode == 2
    assert r.stdout == ""


def test_unknown_flag_is_one_line_with_status_2(cli):
    r = cli("rotation", "--bogus", "1")
    assert r.returncode == 2
    assert r.stdout == ""
    assert len(r.stderr.strip().splitlines()) == 1


def test_rotation_euler_round_trip(cli):
    r = cli("rotation", "--euler", "ZXZ", "30", "45", "60", "--degrees", "--sequence", "ZXZ")
    assert r.returncode == 0, r.stderr
    line = [l for l in r.stdout.splitlines() if l.startswith("euler ZXZ")][0]
    values = [float(x) for x in line.split(":", 1)[1].split("(")[1].split(")")[0].split(",")]
    assert max(abs(a - b) for a, b in zip(values, [30, 45, 60])) < 1e-12


def test_rotation_zero_quaternion_message(cli):
    r = cli("rotation", "--quaternion", "0", "0", "0", "0")
    assert r.returncode == 2
    assert r.stderr.strip() == "poinsot: quaternion: got (0, 0, 0, 0), expected a non-zero quaternion (w, x, y, z)"
