"""`python -m thermogear` runs the command line."""

from thermogear.cli import main

main()
