# cli.mk - the facet command's input parser (src/cli/parse.c) unit-tested on
# its own: it is not part of libfacet, so its test links it directly
# (included by the Makefile; this explicit rule overrides the generic one).
$(BUILD)/tests/test_cli_parse: tests/cli/test_cli_parse.c src/cli/parse.c src/cli/cli.h tests/lib/harness.h
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -D_DEFAULT_SOURCE -Isrc/cli -o $@ tests/cli/test_cli_parse.c src/cli/parse.c -lm
