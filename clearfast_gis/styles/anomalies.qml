<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis hasScaleBasedVisibilityFlag="0" simplifyDrawingHints="1" symbologyReferenceScale="-1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" labelsEnabled="0" simplifyAlgorithm="0" simplifyLocal="1" maxScale="0" simplifyDrawingTol="1" minScale="100000000" simplifyMaxScale="1" version="3.22.16-Białowieża">
  <renderer-v2 forceraster="0" attr="polarity" referencescale="-1" enableorderby="0" type="categorizedSymbol" symbollevels="0">
    <categories>
      <category value="hot" symbol="0" label="Warm by day" render="true"/>
      <category value="cold" symbol="1" label="Cool by day" render="true"/>
    </categories>
    <symbols>
      <symbol name="0" clip_to_extent="1" force_rhr="0" type="fill" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" pass="0" locked="0">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" name="border_width_map_unit_scale" type="QString"/>
            <Option value="0,0,0,0" name="color" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="215,48,39,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.5" name="outline_width" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="no" name="style" type="QString"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="215,48,39,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol name="1" clip_to_extent="1" force_rhr="0" type="fill" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" pass="0" locked="0">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" name="border_width_map_unit_scale" type="QString"/>
            <Option value="0,0,0,0" name="color" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="69,117,180,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.5" name="outline_width" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="no" name="style" type="QString"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="69,117,180,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <rotation/>
    <sizescale/>
  </renderer-v2>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field configurationFlags="None" name="anomaly_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="x">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="y">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lat">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="7" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lon">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="7" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="area_m2">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diameter_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="circularity">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_sigma_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_sigma_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="status">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="polarity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="class_cue">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="n_scans">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_day_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_night_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="fix_quality">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="figure">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_series">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="p_mine">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="priority">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="set_aside_reason">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="short_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="likelihood">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence_pct">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="anomaly_id" name="Suspect id" index="0"/>
    <alias field="x" name="Easting (m, survey UTM)" index="1"/>
    <alias field="y" name="Northing (m, survey UTM)" index="2"/>
    <alias field="lat" name="Latitude (°, WGS84)" index="3"/>
    <alias field="lon" name="Longitude (°, WGS84)" index="4"/>
    <alias field="area_m2" name="Area (m²)" index="5"/>
    <alias field="diameter_m" name="Diameter (m)" index="6"/>
    <alias field="circularity" name="Circularity (0-1)" index="7"/>
    <alias field="depth_m" name="Burial depth (m)" index="8"/>
    <alias field="depth_sigma_m" name="Depth uncertainty, 1σ (m)" index="9"/>
    <alias field="diffusivity_m2s" name="Thermal diffusivity (m²/s)" index="10"/>
    <alias field="diffusivity_sigma_m2s" name="Diffusivity uncertainty, 1σ (m²/s)" index="11"/>
    <alias field="status" name="Characterisation status" index="12"/>
    <alias field="polarity" name="Polarity" index="13"/>
    <alias field="class_cue" name="Class cue" index="14"/>
    <alias field="confidence" name="Class cue confidence (0-1)" index="15"/>
    <alias field="n_scans" name="Scans seen" index="16"/>
    <alias field="contrast_day_k" name="Day contrast (K)" index="17"/>
    <alias field="contrast_night_k" name="Night contrast (K)" index="18"/>
    <alias field="fix_quality" name="GNSS fix quality" index="19"/>
    <alias field="figure" name="Contrast curve" index="20"/>
    <alias field="contrast_series" name="Contrast series (JSON)" index="21"/>
    <alias field="p_mine" name="Mine likelihood (0-1)" index="22"/>
    <alias field="priority" name="Priority (1 = first)" index="23"/>
    <alias field="cue_confidence" name="Class cue confidence (0-1)" index="24"/>
    <alias field="set_aside_reason" name="Set aside because" index="25"/>
    <alias field="short_id" name="Short id" index="26"/>
    <alias field="depth" name="Burial depth ± 1σ" index="27"/>
    <alias field="diffusivity" name="Thermal diffusivity ± 1σ" index="28"/>
    <alias field="likelihood" name="Mine likelihood" index="29"/>
    <alias field="cue_confidence_pct" name="Class cue confidence" index="30"/>
  </aliases>
  <defaults>
    <default applyOnUpdate="0" field="anomaly_id" expression=""/>
    <default applyOnUpdate="0" field="x" expression=""/>
    <default applyOnUpdate="0" field="y" expression=""/>
    <default applyOnUpdate="0" field="lat" expression=""/>
    <default applyOnUpdate="0" field="lon" expression=""/>
    <default applyOnUpdate="0" field="area_m2" expression=""/>
    <default applyOnUpdate="0" field="diameter_m" expression=""/>
    <default applyOnUpdate="0" field="circularity" expression=""/>
    <default applyOnUpdate="0" field="depth_m" expression=""/>
    <default applyOnUpdate="0" field="depth_sigma_m" expression=""/>
    <default applyOnUpdate="0" field="diffusivity_m2s" expression=""/>
    <default applyOnUpdate="0" field="diffusivity_sigma_m2s" expression=""/>
    <default applyOnUpdate="0" field="status" expression=""/>
    <default applyOnUpdate="0" field="polarity" expression=""/>
    <default applyOnUpdate="0" field="class_cue" expression=""/>
    <default applyOnUpdate="0" field="confidence" expression=""/>
    <default applyOnUpdate="0" field="n_scans" expression=""/>
    <default applyOnUpdate="0" field="contrast_day_k" expression=""/>
    <default applyOnUpdate="0" field="contrast_night_k" expression=""/>
    <default applyOnUpdate="0" field="fix_quality" expression=""/>
    <default applyOnUpdate="0" field="figure" expression=""/>
    <default applyOnUpdate="0" field="contrast_series" expression=""/>
    <default applyOnUpdate="0" field="p_mine" expression=""/>
    <default applyOnUpdate="0" field="priority" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence" expression=""/>
    <default applyOnUpdate="0" field="set_aside_reason" expression=""/>
    <default applyOnUpdate="0" field="short_id" expression=""/>
    <default applyOnUpdate="0" field="depth" expression=""/>
    <default applyOnUpdate="0" field="diffusivity" expression=""/>
    <default applyOnUpdate="0" field="likelihood" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence_pct" expression=""/>
  </defaults>
  <constraints>
    <constraint unique_strength="0" field="anomaly_id" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="x" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="y" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="lat" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="lon" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="area_m2" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diameter_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="circularity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth_sigma_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity_m2s" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity_sigma_m2s" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="status" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="polarity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="class_cue" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="confidence" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="n_scans" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_day_k" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_night_k" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="fix_quality" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="figure" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_series" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="p_mine" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="priority" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="cue_confidence" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="set_aside_reason" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="short_id" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="likelihood" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="cue_confidence_pct" constraints="0" notnull_strength="0" exp_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint exp="" desc="" field="anomaly_id"/>
    <constraint exp="" desc="" field="x"/>
    <constraint exp="" desc="" field="y"/>
    <constraint exp="" desc="" field="lat"/>
    <constraint exp="" desc="" field="lon"/>
    <constraint exp="" desc="" field="area_m2"/>
    <constraint exp="" desc="" field="diameter_m"/>
    <constraint exp="" desc="" field="circularity"/>
    <constraint exp="" desc="" field="depth_m"/>
    <constraint exp="" desc="" field="depth_sigma_m"/>
    <constraint exp="" desc="" field="diffusivity_m2s"/>
    <constraint exp="" desc="" field="diffusivity_sigma_m2s"/>
    <constraint exp="" desc="" field="status"/>
    <constraint exp="" desc="" field="polarity"/>
    <constraint exp="" desc="" field="class_cue"/>
    <constraint exp="" desc="" field="confidence"/>
    <constraint exp="" desc="" field="n_scans"/>
    <constraint exp="" desc="" field="contrast_day_k"/>
    <constraint exp="" desc="" field="contrast_night_k"/>
    <constraint exp="" desc="" field="fix_quality"/>
    <constraint exp="" desc="" field="figure"/>
    <constraint exp="" desc="" field="contrast_series"/>
    <constraint exp="" desc="" field="p_mine"/>
    <constraint exp="" desc="" field="priority"/>
    <constraint exp="" desc="" field="cue_confidence"/>
    <constraint exp="" desc="" field="set_aside_reason"/>
    <constraint exp="" desc="" field="short_id"/>
    <constraint exp="" desc="" field="depth"/>
    <constraint exp="" desc="" field="diffusivity"/>
    <constraint exp="" desc="" field="likelihood"/>
    <constraint exp="" desc="" field="cue_confidence_pct"/>
  </constraintExpressions>
  <expressionfields>
    <field comment="" typeName="" name="short_id" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="depth" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="diffusivity" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="likelihood" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="cue_confidence_pct" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="short_id" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="depth" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="diffusivity" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="likelihood" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="cue_confidence_pct" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="short_id" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="depth" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="diffusivity" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="likelihood" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="cue_confidence_pct" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" type="10" length="0"/>
  </expressionfields>
  <attributetableconfig sortOrder="0" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" actionWidgetStyle="dropDown">
    <columns>
      <column width="-1" hidden="0" name="anomaly_id" type="field"/>
      <column width="-1" hidden="0" name="polarity" type="field"/>
      <column width="-1" hidden="0" name="area_m2" type="field"/>
      <column width="-1" hidden="0" name="p_mine" type="field"/>
      <column width="-1" hidden="0" name="priority" type="field"/>
      <column width="-1" hidden="0" name="cue_confidence" type="field"/>
      <column width="-1" hidden="0" name="set_aside_reason" type="field"/>
      <column width="-1" hidden="0" name="short_id" type="field"/>
      <column width="-1" hidden="0" name="depth" type="field"/>
      <column width="-1" hidden="0" name="diffusivity" type="field"/>
      <column width="-1" hidden="0" name="likelihood" type="field"/>
      <column width="-1" hidden="0" name="cue_confidence_pct" type="field"/>
      <column width="-1" hidden="1" type="actions"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer name="Suspect" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Identification" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="short_id" index="26" showLabel="1"/>
        <attributeEditorField name="anomaly_id" index="0" showLabel="1"/>
        <attributeEditorField name="priority" index="23" showLabel="1"/>
        <attributeEditorField name="class_cue" index="14" showLabel="1"/>
        <attributeEditorField name="likelihood" index="29" showLabel="1"/>
        <attributeEditorField name="cue_confidence_pct" index="30" showLabel="1"/>
        <attributeEditorField name="status" index="12" showLabel="1"/>
        <attributeEditorField name="polarity" index="13" showLabel="1"/>
        <attributeEditorField name="set_aside_reason" index="25" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Burial depth and soil" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="depth" index="27" showLabel="1"/>
        <attributeEditorField name="diffusivity" index="28" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Thermal contrast" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="contrast_day_k" index="17" showLabel="1"/>
        <attributeEditorField name="contrast_night_k" index="18" showLabel="1"/>
        <attributeEditorField name="n_scans" index="16" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Shape" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="diameter_m" index="6" showLabel="1"/>
        <attributeEditorField name="area_m2" index="5" showLabel="1"/>
        <attributeEditorField name="circularity" index="7" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="figure" index="20" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Position" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Position" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="x" index="1" showLabel="1"/>
        <attributeEditorField name="y" index="2" showLabel="1"/>
        <attributeEditorField name="lat" index="3" showLabel="1"/>
        <attributeEditorField name="lon" index="4" showLabel="1"/>
        <attributeEditorField name="fix_quality" index="19" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="depth_m" index="8" showLabel="1"/>
        <attributeEditorField name="depth_sigma_m" index="9" showLabel="1"/>
        <attributeEditorField name="diffusivity_m2s" index="10" showLabel="1"/>
        <attributeEditorField name="diffusivity_sigma_m2s" index="11" showLabel="1"/>
        <attributeEditorField name="p_mine" index="22" showLabel="1"/>
        <attributeEditorField name="cue_confidence" index="24" showLabel="1"/>
        <attributeEditorField name="confidence" index="15" showLabel="1"/>
        <attributeEditorField name="contrast_series" index="21" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>2</layerGeometryType>
</qgis>
