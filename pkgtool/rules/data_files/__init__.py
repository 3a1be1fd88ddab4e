"""DAT: data_files, the files an ament_python package installs into its share folder."""
