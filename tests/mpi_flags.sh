# Sourced by the MPI tests (mpi_reference.sh, mpi_validity.sh): mpirun's flags for 2 ranks on
# any machine (oversubscribed, as root where CI runs as root), and the shared-memory transport
# without cross-memory attach, which containers often forbid.
mpirun_flags=(-np 2 --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun_flags+=(--allow-run-as-root)
export OMPI_MCA_btl_vader_single_copy_mechanism=none
