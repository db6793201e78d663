# Prepends the package's install prefix to AMENT_PREFIX_PATH: the shell
# script beside this one does it.
. "$(dirname "${BASH_SOURCE[0]}")/local_setup.sh"
