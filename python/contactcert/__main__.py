"""`python -m contactcert ARGS` runs the contactcert CLI with ARGS: it replaces this process with the executable
(so stdin, stdout, signals and the exit code are the CLI's own). The executable is looked up first in the package
(contactcert/bin, where `pip install .` puts it), then in this interpreter's scripts directory (sysconfig
"scripts": where `cmake --install --prefix VENV` puts programs, e.g. VENV/bin), then on PATH; without one it exits
127 (the shell's "command not found") with a message."""

from __future__ import annotations

import os
import shutil
import sys
import sysconfig

EXIT_NOT_FOUND = 127


def find_cli() -> str | None:
    """The contactcert executable to run: the package's, else the scripts directory's, else the first on PATH,
    else None."""
    return (shutil.which("contactcert", path=os.path.join(os.path.dirname(__file__), "bin"))
            or shutil.which("contactcert", path=sysconfig.get_path("scripts")) or shutil.which("contactcert"))


def main() -> None:
    cli = find_cli()
    if cli is None:
        sys.stderr.write(f"contactcert: no contactcert executable in {sysconfig.get_path('scripts')} or on PATH "
                         "(`cmake --install BUILD --prefix P` puts it in P/bin; the build tree's is BUILD/cli)\n")
        sys.exit(EXIT_NOT_FOUND)
    os.execv(cli, [cli, *sys.argv[1:]])


if __name__ == "__main__":
    main()
