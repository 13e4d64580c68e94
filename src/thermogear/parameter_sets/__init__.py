"""Built-in parameter sets, one TOML file each, named after their source."""
