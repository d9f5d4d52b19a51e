// tb_icarus.v - the committed golden vectors (`facet vectors --format fx_fast
// --hex`) through one kernel of the test top (rtl_all) under Icarus
// Verilog, so the RTL is not tied to one simulator.  Plusargs:
//   +vec=FILE +n=COUNT +name=KERNEL +slot=S +nin=N +bits=32|64 +outs=1|3 +lat=L
// A new vector every clock; every output is compared in order with the
// file's (outs = 3: the RGB form, f0 and albedo repeated on the three
// channels, each channel against brdf_hammon's file), its clock checked
// against the stated latency; then a reset one clock after the last vector
// must clear every sample in flight.  Prints "PASS|FAIL KERNEL: ...".
module tb_icarus;
    reg clk = 1'b0, rst = 1'b1, in_valid = 1'b0;
    reg [319:0] x = 320'd0;
    wire [`RTL_SLOTS-1:0] ov;
    wire [64*`RTL_SLOTS-1:0] y;
    rtl_all dut (clk, rst, in_valid, x, ov, y);

    reg [255:0] mem [0:4095];
    reg [1023:0] vec, name;
    integer n, slot, nin, bits, outs, lat, i, j, o, edge_no, got, bad, late, first_in;
    integer in_edge [0:4095];
    reg [63:0] want, have;

    always #5 clk = !clk;
    always @(posedge clk) edge_no = edge_no + 1;

    // outputs are read at the falling edge, half a clock after they change
    always @(negedge clk) begin
        if (ov[slot] === 1'b1) begin
            if (got >= n) begin
                bad = bad + 1;
                $display("FAIL %0s: an output past the last vector", name);
            end else begin
                if (edge_no != in_edge[got] + lat - 1) begin
                    late = late + 1;
                    if (late < 4) $display("FAIL %0s: vector %0d out at clock %0d, in at %0d, latency %0d", name, got,
                                           edge_no, in_edge[got], lat);
                end
                want = bits == 64 ? mem[got][63:0] : {32'd0, mem[got][31:0]};
                for (o = 0; o < outs; o = o + 1) begin
                    have = y[64*(slot+o) +: 64];
                    if (have !== want) begin
                        bad = bad + 1;
                        if (bad < 6) $display("FAIL %0s[%0d]: vector %0d: rtl %h, golden %h", name, o, got, have, want);
                    end
                end
            end
            got = got + 1;
        end
    end

    initial begin
        edge_no = 0;
        got = 0;
        bad = 0;
        late = 0;
        if (!$value$plusargs("vec=%s", vec) || !$value$plusargs("n=%d", n) || !$value$plusargs("name=%s", name) ||
            !$value$plusargs("slot=%d", slot) || !$value$plusargs("nin=%d", nin) ||
            !$value$plusargs("bits=%d", bits) || !$value$plusargs("outs=%d", outs) || !$value$plusargs("lat=%d", lat)) begin
            $display("ERROR tb_icarus: missing plusargs");
            $finish;
        end
        $readmemh(vec, mem, 0, n - 1);
        repeat (3) @(negedge clk);
        rst = 1'b0;
        for (i = 0; i < n; i = i + 1) begin
            @(negedge clk);
            for (j = 0; j < nin; j = j + 1)
                x[32*j +: 32] = mem[i][bits + 32*(nin-1-j) +: 32];
            if (outs == 3) begin
                x[32*6 +: 32] = x[32*4 +: 32];
                x[32*8 +: 32] = x[32*4 +: 32];
                x[32*7 +: 32] = x[32*5 +: 32];
                x[32*9 +: 32] = x[32*5 +: 32];
            end
            in_valid = 1'b1;
            in_edge[i] = edge_no + 1;
        end
        @(negedge clk);
        in_valid = 1'b0;
        repeat (lat + 2) @(negedge clk);
        if (got != n) begin
            bad = bad + 1;
            $display("FAIL %0s: %0d outputs for %0d vectors", name, got, n);
        end
        // a reset mid-stream: the sample in flight is dropped, and so is the
        // one presented with the reset
        got = n;
        in_valid = 1'b1;
        @(negedge clk);
        rst = 1'b1;
        @(negedge clk);
        rst = 1'b0;
        in_valid = 1'b0;
        repeat (lat + 2) @(negedge clk);
        if (got != n) begin
            bad = bad + 1;
            $display("FAIL %0s: %0d outputs survived the reset", name, got - n);
        end
        if (bad == 0 && late == 0)
            $display("PASS %0s: %0d golden vectors, latency %0d, a new vector every clock, reset clears", name, n, lat);
        else
            $display("FAIL %0s: %0d mismatches, %0d misplaced", name, bad, late);
        $finish;
    end
endmodule
